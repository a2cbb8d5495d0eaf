"""The bridge's mappings: which ROS topic carries what of which robot, and which way (ROS → HLA, HLA → ROS).

The same for ROS 1 and ROS 2 (the topic names are stageros'); :func:`stage_mappings` and
:func:`world_mappings` bridge robots simulated by an HLA federate to ROS, :func:`node_mappings` and
:func:`world_node_mappings` robots simulated by a ROS node to HLA (docs/ros-bridge.md, "Mappings").
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence, Union

from hlacore.federates.robot_world.worldfile import WorldSpec

@dataclass(frozen=True)
class _In:
    """ROS → HLA: what comes in on ``topic`` is about ``robot``."""

    topic: str
    robot: str


@dataclass(frozen=True)
class _Out:
    """HLA → ROS: what is about ``robot`` goes out on ``topic``."""

    robot: str
    topic: str


@dataclass(frozen=True)
class TwistIn(_In):
    """ROS → HLA: ``geometry_msgs/Twist`` on ``topic`` becomes ``cmd_vel(robot, linear.x, angular.z)``."""


@dataclass(frozen=True)
class OdometryOut(_Out):
    """HLA → ROS: the robot's ``odometry`` (``source="odometry"``) or ground-truth ``pose``
    (``source="pose"``, with the odometry's velocities) as ``nav_msgs/Odometry`` on ``topic``."""

    source: str = "odometry"
    frame_id: str = "odom"
    child_frame_id: str = "base_footprint"


@dataclass(frozen=True)
class _BeamsOut(_Out):
    """HLA → ROS: the robot's ``ranges``, its beams spread over ``fov`` radians."""

    fov: float = 0.1  # radians
    range_min: float = 0.0
    range_max: float = 5.0
    frame_id: str = "base_laser_link"


@dataclass(frozen=True)
class ScanOut(_BeamsOut):
    """HLA → ROS: the robot's ``ranges`` as ``sensor_msgs/LaserScan`` (beams from ``-fov/2`` to ``+fov/2``)."""


@dataclass(frozen=True)
class RangeOut(_BeamsOut):
    """HLA → ROS: the robot's nearest beam as ``sensor_msgs/Range`` (ULTRASOUND)."""


@dataclass(frozen=True)
class StallOut(_Out):
    """HLA → ROS: the robot's ``stall`` flag as ``std_msgs/Bool``."""


@dataclass(frozen=True)
class TwistOut(_Out):
    """HLA → ROS: every ``cmd_vel`` interaction naming ``robot`` is published as ``geometry_msgs/Twist``
    (``linear.x``, ``angular.z``) on ``topic``.

    ``ack``: a ``std_msgs/UInt32`` topic on which the node counts the Twists it has taken from ``topic``
    (our stage node's ``/<robot>/cmd_vel_received``; stageros has none). Timed, the bridge then publishes
    the next ``/clock`` only once the count has caught up with what it published: the node cannot step
    before it has applied the commands (ROS keeps no order across topics)."""

    ack: Optional[str] = None


@dataclass(frozen=True)
class OdometryIn(_In):
    """ROS → HLA: ``nav_msgs/Odometry`` on ``topic`` becomes the robot's ``odometry`` attribute (x, y, yaw,
    ``twist.linear.x``, ``twist.angular.z``; ``attribute="odometry"``) or its ground-truth ``pose``
    (x, y, yaw; ``attribute="pose"``)."""

    attribute: str = "odometry"

    def __post_init__(self) -> None:
        if self.attribute not in ("odometry", "pose"):
            raise ValueError(f"OdometryIn feeds 'odometry' or 'pose', not {self.attribute!r}")


@dataclass(frozen=True)
class ScanIn(_In):
    """ROS → HLA: ``sensor_msgs/LaserScan`` on ``topic`` becomes the robot's ``ranges`` (every beam)."""


@dataclass(frozen=True)
class RangeIn(_In):
    """ROS → HLA: ``sensor_msgs/Range`` on ``topic`` becomes the robot's ``ranges`` as one beam (for a
    robot whose only sensor is a sonar; do not map a ScanIn of the same robot too)."""


@dataclass(frozen=True)
class StallIn(_In):
    """ROS → HLA: ``std_msgs/Bool`` on ``topic`` becomes the robot's ``stall`` flag (not stamped: it
    travels with the next update of the robot, never awaited)."""


Mapping = Union[TwistIn, OdometryOut, ScanOut, RangeOut, StallOut, TwistOut, OdometryIn, ScanIn, RangeIn, StallIn]
StateIn = (OdometryIn, ScanIn, RangeIn, StallIn)  #: the ROS → HLA state mappings


def stage_mappings(robot: str, prefix: Optional[str] = None, fov: float = 0.1, range_min: float = 0.0,
                   range_max: float = 5.0) -> list[Mapping]:
    """stageros' topics for one robot under ``prefix`` (default ``/<robot>``): ``cmd_vel`` in; ``odom``,
    ``base_pose_ground_truth``, ``base_scan`` out; plus ``range`` (nearest beam) and ``stall``."""
    p = f"/{robot}" if prefix is None else prefix.rstrip("/")
    frame = p.lstrip("/")
    odom_frame = f"{frame}/odom" if frame else "odom"
    laser_frame = f"{frame}/base_laser_link" if frame else "base_laser_link"
    return [
        TwistIn(f"{p}/cmd_vel", robot),
        OdometryOut(robot, f"{p}/odom", "odometry", odom_frame),
        OdometryOut(robot, f"{p}/base_pose_ground_truth", "pose", odom_frame),
        ScanOut(robot, f"{p}/base_scan", fov, range_min, range_max, laser_frame),
        RangeOut(robot, f"{p}/range", fov, range_min, range_max, laser_frame),
        StallOut(robot, f"{p}/stall"),
    ]


def world_mappings(spec: WorldSpec, robots: Optional[Sequence[str]] = None) -> list[Mapping]:
    """:func:`stage_mappings` for each robot of a world (or the named ones), with the first ranger's
    field of view and range limits."""
    out: list[Mapping] = []
    for r in spec.robots:
        if robots is not None and r.name not in robots:
            continue
        if r.sensors:
            s = r.sensors[0]
            out.extend(stage_mappings(r.name, fov=s.fov, range_min=s.range_min, range_max=s.range_max))
        else:
            out.extend(stage_mappings(r.name))
    return out


def node_mappings(robot: str, prefix: Optional[str] = None, sensor: Optional[str] = "scan",
                  acks: bool = False) -> list[Mapping]:
    """The other direction of :func:`stage_mappings`, for a robot simulated by a stageros-style ROS node
    under ``prefix`` (default ``/<robot>``): ``cmd_vel`` interactions out as Twist on ``cmd_vel`` (with
    ``acks``, acknowledged on ``cmd_vel_received``: our stage node's); ``odom`` → ``odometry``,
    ``base_pose_ground_truth`` → ``pose``, ``base_scan`` (``sensor="scan"``) or ``range``
    (``sensor="range"``; ``None``: no sensor) → ``ranges``, ``stall`` → ``stall`` in."""
    p = f"/{robot}" if prefix is None else prefix.rstrip("/")
    ack = f"{p}/cmd_vel_received" if acks else None
    out: list[Mapping] = [TwistOut(robot, f"{p}/cmd_vel", ack), OdometryIn(f"{p}/odom", robot, "odometry"),
                          OdometryIn(f"{p}/base_pose_ground_truth", robot, "pose")]
    if sensor == "scan":
        out.append(ScanIn(f"{p}/base_scan", robot))
    elif sensor == "range":
        out.append(RangeIn(f"{p}/range", robot))
    elif sensor is not None:
        raise ValueError(f"sensor is 'scan', 'range' or None, not {sensor!r}")
    out.append(StallIn(f"{p}/stall", robot))
    return out


def world_node_mappings(spec: WorldSpec, robots: Optional[Sequence[str]] = None,
                        acks: bool = False) -> list[Mapping]:
    """:func:`node_mappings` for each robot of a world simulated by a ROS node (or the named ones); robots
    without a ranger get no sensor mapping."""
    return [m for r in spec.robots if robots is None or r.name in robots
            for m in node_mappings(r.name, sensor="scan" if r.sensors else None, acks=acks)]
