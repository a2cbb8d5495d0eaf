"""Make Debian's ROS 1 Python packages importable from the project's Python, and only those.

Debian ships rospy and the message packages for its own ``/usr/bin/python3`` in
``/usr/lib/python3/dist-packages``. Their compiled parts are built for the CPython 3.11 ABI, so they
also load under another CPython 3.11 (the project's venv). Putting the whole of dist-packages on
``sys.path`` would also expose every other Debian package (an old numpy, matplotlib...) to the venv, so
:func:`enable` installs instead a meta-path finder, **last** on ``sys.meta_path`` (the venv's own
packages always win), that answers only for the top-level names of ROS's Python packages and their few
pure dependencies (:data:`ROS_MODULES`, plus any ``*_msgs`` / ``*_srvs`` message package) and looks them
up in that one directory. Submodules follow their package's ``__path__`` as usual.

``HLACORE_ROS_DIST_PACKAGES`` overrides the directory (tests point it at an empty one to see the error).
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import os
import sys
from types import ModuleType
from typing import Optional, Sequence

#: Where Debian's python3-ros* packages live.
DEFAULT_DIST_PACKAGES = "/usr/lib/python3/dist-packages"
#: The Debian packages the bridge needs (scripts/install-ros.sh installs them).
DEBIAN_PACKAGES = ("ros-core", "python3-rospy", "python3-geometry-msgs", "python3-nav-msgs",
                   "python3-sensor-msgs", "python3-std-msgs")
#: Top-level modules served from dist-packages (when the venv has none of that name): ROS's Python
#: packages and what they import.
ROS_MODULES = frozenset({
    "rospy", "rosgraph", "roslib", "rospkg", "genpy", "genmsg", "catkin", "catkin_pkg", "roscpp",
    "rosmaster", "rosparam", "rostopic", "rosnode", "rosmsg", "rosservice", "roslaunch", "rosbag", "roslz4",
    "rosclean", "message_filters", "yaml", "_yaml", "netifaces", "defusedxml", "dateutil", "docutils",
    "pyparsing", "six",
})

INSTALL_HINT = ("the ROS bridge needs ROS 1 (rospy and the message packages) from Debian: "
                "apt-get install -y --no-install-recommends " + " ".join(DEBIAN_PACKAGES) +
                "  (./scripts/install-ros.sh does it)")


def dist_packages() -> str:
    """The directory searched for the ROS modules (``$HLACORE_ROS_DIST_PACKAGES`` or Debian's)."""
    return os.environ.get("HLACORE_ROS_DIST_PACKAGES", DEFAULT_DIST_PACKAGES)


def is_ros_module(name: str) -> bool:
    """True for the top-level module names the finder serves."""
    return name in ROS_MODULES or name.endswith("_msgs") or name.endswith("_srvs")


class RosFinder(importlib.abc.MetaPathFinder):
    """Finds the ROS top-level modules (see :func:`is_ros_module`) in one directory, nothing else."""

    def __init__(self, directory: str) -> None:
        self.directory = directory

    def find_spec(self, fullname: str, path: Optional[Sequence[str]] = None,
                  target: Optional[ModuleType] = None) -> Optional[importlib.machinery.ModuleSpec]:
        """The spec of a ROS top-level module found in :attr:`directory`; None for any other name."""
        if path is not None or "." in fullname or not is_ros_module(fullname):
            return None
        return importlib.machinery.PathFinder.find_spec(fullname, [self.directory])

    def __repr__(self) -> str:
        return f"RosFinder({self.directory!r})"


def enable() -> RosFinder:
    """Append the :class:`RosFinder` to ``sys.meta_path`` once (idempotent) and return it."""
    directory = dist_packages()
    for finder in sys.meta_path:
        if isinstance(finder, RosFinder) and finder.directory == directory:
            return finder
    finder = RosFinder(directory)
    sys.meta_path.append(finder)
    importlib.invalidate_caches()
    return finder


#: The message modules the bridge uses (imported, and so checked, by :func:`import_rospy`).
MESSAGE_MODULES = ("std_msgs.msg", "geometry_msgs.msg", "nav_msgs.msg", "sensor_msgs.msg", "rosgraph_msgs.msg")


def _import_all() -> ModuleType:
    rospy = importlib.import_module("rospy")
    for name in MESSAGE_MODULES:
        importlib.import_module(name)
    return rospy


def import_rospy() -> ModuleType:
    """Import rospy and the bridge's message packages (from the venv if it has them, else Debian's) and
    return rospy; an ImportError saying what to install when one is missing."""
    try:
        return _import_all()
    except ImportError:
        pass
    enable()
    try:
        return _import_all()
    except ImportError as error:
        raise ImportError(f"{INSTALL_HINT}; looked in {dist_packages()} ({error})") from error
