"""The ROS 1 bridge: a rospy node and an HLA federate of the robot world in one process (docs/ros-bridge.md).

Importing it imports Debian's rospy (see :mod:`.ros_import`); without ROS installed it raises an
ImportError that names the Debian packages to install.
"""

from .ros_import import INSTALL_HINT, import_rospy

import_rospy()

from .bridge import (  # noqa: E402
    Mapping,
    OdometryOut,
    RangeOut,
    RosBridge,
    ScanOut,
    StallOut,
    TwistIn,
    stage_mappings,
    world_mappings,
    yaw_quaternion,
)

__all__ = [
    "INSTALL_HINT",
    "Mapping",
    "OdometryOut",
    "RangeOut",
    "RosBridge",
    "ScanOut",
    "StallOut",
    "TwistIn",
    "import_rospy",
    "stage_mappings",
    "world_mappings",
    "yaw_quaternion",
]
