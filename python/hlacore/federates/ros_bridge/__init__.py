"""The ROS 1 bridge: a rospy node and an HLA federate of the robot world in one process (docs/ros-bridge.md).

Importing it imports Debian's rospy (see :mod:`.ros_import`); without ROS installed it raises an
ImportError that names the Debian packages to install. Also here: :mod:`.stage_node` (the robot world as a
stageros-style ROS node), :mod:`.master` (a ROS master for one run), :mod:`.children` (child processes)
and :mod:`.runner` (the world federate on a thread beside the bridge, for scenario runs).

Federates layer: imports the core and :mod:`hlacore.federates.robot_world`.
"""

from .ros_import import INSTALL_HINT, import_rospy

import_rospy()

from .bridge import (  # noqa: E402
    Mapping,
    OdometryIn,
    OdometryOut,
    RangeIn,
    RangeOut,
    RosBridge,
    ScanIn,
    ScanOut,
    StallIn,
    StallOut,
    TwistIn,
    TwistOut,
    node_mappings,
    stage_mappings,
    world_mappings,
    world_node_mappings,
    yaw_of,
    yaw_quaternion,
)

__all__ = [
    "INSTALL_HINT",
    "Mapping",
    "OdometryIn",
    "OdometryOut",
    "RangeIn",
    "RangeOut",
    "RosBridge",
    "ScanIn",
    "ScanOut",
    "StallIn",
    "StallOut",
    "TwistIn",
    "TwistOut",
    "import_rospy",
    "node_mappings",
    "stage_mappings",
    "world_mappings",
    "world_node_mappings",
    "yaw_of",
    "yaw_quaternion",
]
