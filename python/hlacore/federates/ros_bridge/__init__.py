"""The ROS bridge: a ROS node (ROS 1 or ROS 2) and an HLA federate of the robot world in one process
(docs/ros-bridge.md).

The bridge and the stage node are written once against :class:`~.ros_api.RosApi`; :mod:`.ros1` implements it
with Debian's rospy (:mod:`.ros_import`), :mod:`.ros2` with rclpy from ROS 2 Kilted's wheels
(:mod:`.ros2_env`: the environment a ROS 2 process needs). Importing this package imports neither: the ROS
of a bridge is chosen when it is built (:func:`~.ros_api.select`), and a missing one is an ImportError that
says what to install. Also here: :mod:`.stage_node` (the robot world as a stageros-style ROS node),
:mod:`.master` (a ROS 1 master for one run), :mod:`.children` (child processes) and :mod:`.runner` (the
world federate on a thread beside the bridge, for scenario runs).

Federates layer: imports the core and :mod:`hlacore.federates.robot_world`.
"""

from .bridge import (
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
)
from .ros_api import RosApi
from .versions import detect, select
from .ros_import import INSTALL_HINT, import_rospy

__all__ = [
    "INSTALL_HINT",
    "Mapping",
    "OdometryIn",
    "OdometryOut",
    "RangeIn",
    "RangeOut",
    "RosApi",
    "RosBridge",
    "ScanIn",
    "ScanOut",
    "StallIn",
    "StallOut",
    "TwistIn",
    "TwistOut",
    "import_rospy",
    "detect",
    "node_mappings",
    "stage_mappings",
    "world_mappings",
    "world_node_mappings",
    "select",
    "yaw_of",
]
