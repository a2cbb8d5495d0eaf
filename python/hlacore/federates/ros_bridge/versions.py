"""Which ROS a bridge or a stage node speaks: named (``--ros 1`` / ``--ros 2``) or found (:func:`detect`), and
its :class:`~.ros_api.RosApi` (:func:`select`)."""

from __future__ import annotations

import os
from typing import Optional

from . import ros2_env
from .ros_api import RosApi

VERSIONS = (1, 2)


def detect() -> int:
    """Which ROS to bridge when none is named: ``$ROS_VERSION`` when set (ROS's setup scripts set it);
    else ROS 1 when ``$ROS_MASTER_URI`` is set (a ROS 1 user's shell); else ROS 2 when its wheels are
    installed (:mod:`.ros2_env`) or rclpy is importable, else ROS 1."""
    version = os.environ.get("ROS_VERSION", "")
    if version in ("1", "2"):
        return int(version)
    if os.environ.get("ROS_MASTER_URI"):
        return 1
    return 2 if ros2_env.installed() or ros2_env.sourced() else 1


def select(version: Optional[int] = None) -> RosApi:
    """The :class:`RosApi` of ROS ``version`` (1 or 2; None: :func:`detect`). ImportError, saying what to
    install, when that ROS is missing."""
    if version is None:
        version = detect()
    if version == 1:
        from .ros1 import Ros1

        return Ros1()
    if version == 2:
        from .ros2 import Ros2

        return Ros2()
    raise ValueError(f"ROS version is 1 or 2, not {version!r}")
