"""The ROS calls of the bridge and the stage node, one interface for ROS 1 and ROS 2.

The bridge (:mod:`.bridge`) and the stage node (:mod:`.stage_node`) are written once against
:class:`RosApi`; :mod:`.ros1` implements it with rospy (Debian's ROS 1, a master), :mod:`.ros2` with rclpy
(ROS 2 Kilted's wheels, DDS). The messages have the same packages, names and fields in both (``Twist``,
``Odometry``, ``LaserScan``, ``Range``, ``Bool``, ``UInt32``, ``Clock``); what differs is small: how a node
starts and stops, publishers and subscribers (QoS in ROS 2), the time type of ``header.stamp``, how
connections are counted, and ``use_sim_time`` (a global parameter in ROS 1, each node's own in ROS 2).

:func:`.versions.select` picks the implementation: ``--ros 1`` / ``--ros 2``, or found from what is
installed (:func:`.versions.detect`).
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from dataclasses import dataclass
from typing import Any, Callable, Optional

from hlacore import fed
from hlacore.federates.robot_world import codec

#: What a subscriber's ``on_mismatch`` is called with: the topic, and what does not match (a publisher of
#: another type, or with a QoS the subscription cannot take): the messages of that publisher never arrive.
Mismatch = Callable[[str, str], None]


@dataclass(frozen=True)
class Messages:
    """The message classes the bridge and the stage node use, from one ROS."""

    Twist: Any
    Quaternion: Any
    Odometry: Any
    Clock: Any
    LaserScan: Any
    Range: Any
    Bool: Any
    UInt32: Any


class RosApi(ABC):
    """One ROS, as the bridge and the stage node use it: one node per process, its publishers and
    subscribers, stamps, ``/clock``. Subscriber callbacks run on the ROS library's threads."""

    version: int  #: 1 or 2
    msgs: Messages

    @abstractmethod
    def init_node(self, name: str, timeout: float = 10.0, sim_time: bool = False) -> None:
        """Start this process's node ``name`` (ROS 1: once the master answers, within ``timeout`` s);
        ``sim_time``: the node's own clock follows ``/clock``."""

    @abstractmethod
    def publisher(self, topic: str, kind: Any, reliable: bool = True, synchronous: bool = False,
                  latched: bool = False) -> Any:
        """A publisher of ``kind`` on ``topic``; ``reliable`` False: best effort (ROS 2's sensor-data QoS;
        ROS 1's TCPROS is always reliable); ``synchronous``: ``publish`` has written the message when it
        returns; ``latched``: a subscriber that connects later still gets the last message (ROS 1's latch,
        ROS 2's transient local durability), so none is lost to a connection still being made."""

    @abstractmethod
    def subscriber(self, topic: str, kind: Any, callback: Callable[[Any], None], reliable: bool = True,
                   on_mismatch: Optional[Mismatch] = None, latched: bool = False) -> Any:
        """Call ``callback(msg)`` for each message on ``topic``. ``on_mismatch(topic, what)``: a publisher on
        the topic does not match (another type, an incompatible QoS); its messages never arrive. ``latched``:
        also the last message a latched publisher sent before the connection (ROS 2: transient local)."""

    @abstractmethod
    def publisher_connections(self, pub: Any) -> int:
        """How many subscribers ``pub`` reaches."""

    @abstractmethod
    def subscriber_connections(self, sub: Any) -> int:
        """How many publishers ``sub`` hears."""

    @abstractmethod
    def topic_of(self, sub: Any) -> str:
        """The resolved topic of a subscriber."""

    @abstractmethod
    def unsubscribe(self, sub: Any) -> None:
        """Drop a subscriber."""

    @abstractmethod
    def stamp(self, seconds: float) -> Any:
        """The ``header.stamp`` value of a time in seconds (whole nanoseconds)."""

    @abstractmethod
    def seconds(self, stamp: Any) -> float:
        """A ``header.stamp`` value in seconds."""

    @abstractmethod
    def now(self) -> Any:
        """The node's time as a ``header.stamp`` value (ROS time: ``/clock`` when the node follows it)."""

    @abstractmethod
    def set_use_sim_time(self) -> None:
        """Tell the nodes to follow ``/clock``: ROS 1's global ``/use_sim_time``; ROS 2 has no global
        parameter, so this node's own (others are started with ``-p use_sim_time:=true``)."""

    @abstractmethod
    def ok(self) -> bool:
        """False once the node is shut down."""

    @abstractmethod
    def shutdown(self, reason: str) -> None:
        """Shut this process's node down."""

    def foreign_publishers(self, sub: Any) -> list[str]:
        """The types of the publishers on ``sub``'s topic that are not of its type (their messages never
        arrive). ROS 1: none is ever seen (rospy refuses such a connection at its handshake, and logs it)."""
        return []

    #: MCAP's name of this ROS's wire format (``ros1`` or ``cdr``), for :mod:`.recorder`
    message_encoding: str

    @abstractmethod
    def serialize(self, msg: Any) -> bytes:
        """``msg`` as it travels on the wire (ROS 1's serialization, ROS 2's CDR)."""

    @abstractmethod
    def schema(self, kind: Any) -> tuple[str, str, bytes]:
        """The MCAP schema of a message class: its name (``pkg/Type``), encoding (``ros1msg`` /
        ``ros2msg``) and text (its definition, then each type it uses, as rosbag writes them)."""

    def clock(self, seconds: float) -> Any:
        """A ``rosgraph_msgs/Clock`` message of a time in seconds."""
        return self.msgs.Clock(clock=self.stamp(seconds))

    def quaternion(self, theta: float) -> Any:
        """The quaternion of a rotation by ``theta`` about z."""
        return self.msgs.Quaternion(x=0.0, y=0.0, z=math.sin(theta / 2.0), w=math.cos(theta / 2.0))


def yaw_of(q: Any) -> float:
    """The heading (rotation about z) of a quaternion (any ROS's, or anything with x, y, z, w)."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def reliable(attribute_or_interaction: str) -> bool:
    """The QoS of a bridged topic from the HLA transport of what it carries, as the robot world's FOM
    declares it: ``reliable`` ↔ reliable, ``best_effort`` ↔ best effort (ROS 2's sensor-data QoS).
    ``attribute_or_interaction``: a ``WorldRobot`` attribute, or ``cmd_vel``."""
    fom = _fom()
    if attribute_or_interaction == codec.INTERACTION:
        return fom.interaction_class(codec.INTERACTION).transport == "reliable"
    cls = fom.object_class(codec.OBJECT_CLASS)
    return cls.attribute(attribute_or_interaction).transport == "reliable"


_FOM: list[fed.Fom] = []


def _fom() -> fed.Fom:
    if not _FOM:
        _FOM.append(fed.parse(codec.FOM_PATH))
    return _FOM[0]
