"""What a process needs to run ROS 2 from the PyPI wheels (ros2-requirements.txt), in one place.

:mod:`.install_ros2` installs the wheels under a prefix of their own, ``<venv>/ros2``, not into the
venv's site-packages: ROS 2's message packages have the top-level names of ROS 1's (``std_msgs``,
``geometry_msgs``, ...), and in the venv they would shadow Debian's ROS 1 messages, which rospy then fails
to import. Under the prefix they are seen only by the processes started with :func:`environment`. There
rclpy and the messages are in ``<prefix>/lib/python3.X/site-packages``, the C libraries in ``<prefix>/lib``
and in ``site-packages/ros_*.libs`` (libraries that auditwheel vendored under hashed names: one wheel's
extension needs another wheel's ``.libs``, which no RPATH names). So a ROS 2 process needs, **when it
starts** (the dynamic loader reads ``LD_LIBRARY_PATH`` only then):

* ``PYTHONPATH``: the prefix's site-packages;
* ``LD_LIBRARY_PATH``: ``<prefix>/lib`` and every ``ros_*.libs`` directory;
* ``AMENT_PREFIX_PATH=<prefix>``: the ament index (``<prefix>/share/ament_index``), where
  ``rmw_implementation`` looks up the middleware and rosidl the type supports;
* ``RMW_IMPLEMENTATION=rmw_fastrtps_cpp``: the only middleware installed (the default would be the same,
  named here so that a user's other setting does not pick one that is missing);
* ``RMW_FASTRTPS_PUBLICATION_MODE=SYNCHRONOUS``: ``publish`` writes the message before it returns (the
  bridge publishes a grant's Twists before the next ``/clock``; rospy's bridge does the same with
  ``queue_size=None``), and no extra sending thread per publisher;
* ``FASTDDS_DEFAULT_PROFILES_FILE``: this package's ``fastdds.xml`` (unless one is set already), whose only
  change to Fast DDS's defaults is a 3 s participant lease (announced every second) instead of 20 s: a node
  killed without a goodbye is seen gone within seconds (by peers that have this lease from *it*: a user's
  robot node started without this environment keeps the 20 s);
* optionally ``ROS_DOMAIN_ID`` (DDS participants of other domains never match: a test's own domain) and
  ``ROS_LOG_DIR`` (rcl writes a log file per process, by default under ``~/.ros/log``).

:func:`environment` builds that environment for a child process; :func:`reexec_with_ros2` lets a command
(``python -m hlacore.federates.ros_bridge --ros 2``) give it to itself by re-executing once; ``python -m
hlacore.federates.ros_bridge.ros2_env COMMAND`` runs any command with it (a user's own ROS 2 node).
``HLACORE_ROS2_PREFIX`` names another prefix than ``<venv>/ros2`` (a sourced ROS 2 install needs none of
this: its setup script sets these variables).
"""

from __future__ import annotations

import glob
import importlib.util
import os
import sys
from typing import Mapping, Optional

from .install_ros2 import COMMAND as INSTALL_COMMAND, prefix  # how and where the wheels are installed

#: The middleware the pinned wheels bring.
RMW_IMPLEMENTATION = "rmw_fastrtps_cpp"
#: Set in the environment :func:`environment` builds: the process has it (see :func:`ready`). The wheels'
#: optional bootstrapper (not installed by :mod:`.install_ros2`) reads its own guard, set too, so that it
#: would not re-execute such a process again.
READY_FLAG = "HLACORE_ROS2_ENV"
INSTALL_HINT = ("the ROS 2 bridge needs ROS 2 Kilted's wheels (rclpy, rmw_fastrtps_cpp and the message "
                f"packages) for this Python: {INSTALL_COMMAND} installs the pinned set")


#: Fast DDS's XML profile for the processes started with :func:`environment` (see the module docstring).
PROFILES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fastdds.xml")


def site_packages(root: Optional[str] = None) -> str:
    """The site-packages directory of ``root`` (default :func:`prefix`) for this Python version."""
    version = f"python{sys.version_info.major}.{sys.version_info.minor}"
    return os.path.join(root or prefix(), "lib", version, "site-packages")


def library_dirs(root: Optional[str] = None) -> list[str]:
    """``<prefix>/lib`` and the wheels' ``ros_*.libs`` directories, sorted."""
    base = root or prefix()
    return [os.path.join(base, "lib"), *sorted(glob.glob(os.path.join(site_packages(base), "ros_*.libs")))]


def installed(root: Optional[str] = None) -> bool:
    """Whether the ROS 2 wheels are under the prefix: rclpy and the Fast DDS middleware's library."""
    base = root or prefix()
    return (os.path.isfile(os.path.join(site_packages(base), "rclpy", "__init__.py"))
            and os.path.exists(os.path.join(base, "lib", f"lib{RMW_IMPLEMENTATION}.so")))


def sourced() -> bool:
    """Whether this process can import rclpy as it is (a ROS 2 installation's setup script was sourced)."""
    return importlib.util.find_spec("rclpy") is not None


def environment(base: Optional[Mapping[str, str]] = None, domain_id: Optional[int] = None,
                log_dir: Optional[str] = None) -> dict[str, str]:
    """``base`` (default ``os.environ``) with what a ROS 2 process needs (see the module docstring):
    the Python and library paths prepended, the ament prefix, the middleware, and ``ROS_DOMAIN_ID`` /
    ``ROS_LOG_DIR`` when given."""
    env = dict(os.environ if base is None else base)
    root = prefix()
    packages = site_packages(root)
    python = [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p and p != packages]
    env["PYTHONPATH"] = os.pathsep.join([packages, *python])
    dirs = library_dirs(root)
    old = [d for d in env.get("LD_LIBRARY_PATH", "").split(os.pathsep) if d and d not in dirs]
    env["LD_LIBRARY_PATH"] = os.pathsep.join(dirs + old)
    ament = [p for p in env.get("AMENT_PREFIX_PATH", "").split(os.pathsep) if p and p != root]
    env["AMENT_PREFIX_PATH"] = os.pathsep.join([root, *ament])
    env["RMW_IMPLEMENTATION"] = RMW_IMPLEMENTATION
    env["RMW_FASTRTPS_PUBLICATION_MODE"] = "SYNCHRONOUS"
    env.setdefault("FASTDDS_DEFAULT_PROFILES_FILE", PROFILES)
    env[READY_FLAG] = root
    env["_ROS_WHEELS_BOOTSTRAP_COMPLETE"] = "1"
    if domain_id is not None:
        env["ROS_DOMAIN_ID"] = str(domain_id)
    if log_dir is not None:
        env["ROS_LOG_DIR"] = log_dir
    return env


def ready(env: Optional[Mapping[str, str]] = None) -> bool:
    """Whether ``env`` (default this process's) was built by :func:`environment` for this prefix: a process
    started with it can import rclpy."""
    return (os.environ if env is None else env).get(READY_FLAG) == prefix()


def reexec_with_ros2() -> None:
    """Re-execute this process (same interpreter, same arguments) with :func:`environment` unless it has it
    already: for commands that import rclpy when started from a plain shell. Returns only when ready, or at
    once when the wheels are not installed but rclpy is importable (a sourced ROS 2 installation)."""
    if ready():
        return
    if not installed():
        if sourced():
            return
        raise ImportError(INSTALL_HINT)
    sys.stdout.flush()
    sys.stderr.flush()
    os.execve(sys.executable, sys.orig_argv, environment())


def main(argv: Optional[list[str]] = None) -> int:
    """``python -m hlacore.federates.ros_bridge.ros2_env [COMMAND ...]``: run COMMAND with the ROS 2
    environment (it replaces this process), or, without one, print it as ``export`` lines for a shell
    (``eval "$(python -m hlacore.federates.ros_bridge.ros2_env)"``)."""
    import shlex

    args = sys.argv[1:] if argv is None else argv
    if not installed():
        print(INSTALL_HINT, file=sys.stderr)
        return 2
    env = environment()
    if not args:
        for name in ("PYTHONPATH", "LD_LIBRARY_PATH", "AMENT_PREFIX_PATH", "RMW_IMPLEMENTATION",
                     "RMW_FASTRTPS_PUBLICATION_MODE", "FASTDDS_DEFAULT_PROFILES_FILE", READY_FLAG):
            print(f"export {name}={shlex.quote(env[name])}")
        return 0
    command = [sys.executable if args[0] in ("python", "python3") else args[0], *args[1:]]
    os.execvpe(command[0], command, env)
    return 127  # not reached


if __name__ == "__main__":
    sys.exit(main())
