"""Install ROS 2 Kilted's pinned wheels from PyPI for the ROS 2 bridge: ``python -m
hlacore.federates.ros_bridge.install_ros2 [--prefix DIR] [--check]``.

The set is ``ros2-requirements.txt`` beside this file (it says why each wheel is pinned to its version and
hash); pip installs the missing ones with ``--no-deps --require-hashes`` under a prefix of their own,
``<venv>/ros2`` by default (:mod:`.ros2_env` says why not in site-packages, and gives ROS 2 processes that
prefix). When every pin is there it only checks. ``--check`` lists what is missing and exits 1 if anything is.

Standard library only, so that ``scripts/install-ros2.sh`` can run this file before hlacore is built.
"""

from __future__ import annotations

import argparse
import importlib.metadata as metadata
import os
import pathlib
import re
import subprocess
import sys
import sysconfig
import tempfile
from typing import Optional, Sequence

#: The command, as the hints that it is needed name it.
COMMAND = "python -m hlacore.federates.ros_bridge.install_ros2"
#: The pinned wheels, shipped with the package.
REQUIREMENTS = pathlib.Path(__file__).with_name("ros2-requirements.txt")
#: The prefix under the venv where the wheels go.
PREFIX_NAME = "ros2"
#: A requirement line ending so is a common package installed only when the venv has none at any version.
IF_MISSING = "# if missing"


def prefix() -> str:
    """Where the wheels are: ``$HLACORE_ROS2_PREFIX``, else ``ros2`` under this interpreter's prefix (the
    venv)."""
    return os.environ.get("HLACORE_ROS2_PREFIX") or os.path.join(sys.prefix, PREFIX_NAME)


def _name(distribution: str) -> str:
    return re.sub(r"[-_.]+", "-", distribution).lower()


def missing(root: Optional[str] = None, requirements: pathlib.Path = REQUIREMENTS) -> list[str]:
    """The requirement lines (``name==version --hash=...``) whose wheel is not under ``root`` (default
    :func:`prefix`) at that version; an ``# if missing`` one only when neither there nor in this Python."""
    packages = sysconfig.get_path("purelib", vars={"base": root or prefix(), "platbase": root or prefix()})
    under_prefix = {_name(d.metadata["Name"]): d.version for d in metadata.distributions(path=[packages])}
    here = {_name(d.metadata["Name"]) for d in metadata.distributions()}
    lines = []
    for line in requirements.read_text().splitlines():
        spec = line.split("#", 1)[0].strip()
        if not spec:
            continue
        name, version = spec.split()[0].split("==")
        if line.rstrip().endswith(IF_MISSING):
            if _name(name) not in under_prefix and _name(name) not in here:
                lines.append(spec)
        elif under_prefix.get(_name(name)) != version:
            lines.append(spec)
    return lines


def install(root: Optional[str] = None) -> int:
    """pip-install what :func:`missing` lists under ``root``; pip's exit status (0 when nothing was missing)."""
    root = root or prefix()
    wanted = missing(root)
    if not wanted:
        return 0
    print(f"installing {len(wanted)} pinned wheels of ROS 2 Kilted from PyPI under {root} (rclpy 9.1.2, "
          "rmw_fastrtps_cpp, the message packages; about 60 MB to download, 160 MB installed), for the ROS 2 "
          f"bridge; exact versions and hashes: {REQUIREMENTS}", file=sys.stderr)
    with tempfile.NamedTemporaryFile("w", suffix=".txt", prefix="ros2-missing-") as listed:
        listed.write("\n".join(wanted) + "\n")
        listed.flush()
        return subprocess.call([sys.executable, "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
                                "--no-deps", "--require-hashes", "--no-warn-script-location", "--prefix", root,
                                "-r", listed.name])


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command (see the module's docstring)."""
    parser = argparse.ArgumentParser(prog=COMMAND,
                                     description="Install ROS 2 Kilted's pinned wheels for the ROS 2 bridge.")
    parser.add_argument("--prefix", default=None, help=f"where to install (default: {prefix()})")
    parser.add_argument("--check", action="store_true", help="list the missing wheels, install nothing")
    args = parser.parse_args(argv)
    if args.check:
        wanted = missing(args.prefix)
        print("\n".join(wanted) if wanted else f"every pinned wheel is under {args.prefix or prefix()}")
        return 1 if wanted else 0
    return install(args.prefix)


if __name__ == "__main__":
    sys.exit(main())
