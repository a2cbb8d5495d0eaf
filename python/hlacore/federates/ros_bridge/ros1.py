""":class:`~.ros_api.RosApi` on ROS 1: Debian's rospy (:mod:`.ros_import`) and a ROS master."""

from __future__ import annotations

import time
import warnings
from typing import Any, Callable, Optional

from .ros_api import Messages, RosApi, Mismatch
from .ros_import import import_rospy


class Ros1(RosApi):
    """rospy: TCPROS connections through the master at ``$ROS_MASTER_URI``; callbacks on rospy's threads
    (one per connection). Every topic is reliable (TCP). A publisher of another type is refused by rospy
    itself at the connection handshake (it logs the mismatch), so ``on_mismatch`` is never called."""

    version = 1
    message_encoding = "ros1"

    def __init__(self) -> None:
        self.rospy = import_rospy()
        from geometry_msgs.msg import Quaternion, Twist
        from nav_msgs.msg import Odometry
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import LaserScan, Range
        from std_msgs.msg import Bool, UInt32

        self.msgs = Messages(Twist, Quaternion, Odometry, Clock, LaserScan, Range, Bool, UInt32)

    def init_node(self, name: str, timeout: float = 10.0, sim_time: bool = False) -> None:
        """Wait (``timeout`` s) for the master, then ``rospy.init_node`` (ROS time follows ``/clock`` when
        ``/use_sim_time`` is set, whatever ``sim_time`` says)."""
        import rosgraph

        deadline = time.monotonic() + timeout
        while not rosgraph.is_master_online():
            if time.monotonic() > deadline:
                raise TimeoutError(f"no ROS master at {rosgraph.get_master_uri()} within {timeout} s")
            time.sleep(0.05)
        self.rospy.init_node(name, anonymous=False, disable_signals=True)

    def publisher(self, topic: str, kind: Any, reliable: bool = True, synchronous: bool = False,
                  latched: bool = False) -> Any:
        """``rospy.Publisher``; ``synchronous``: ``queue_size=None`` (publish writes before it returns);
        ``latched``: ``latch=True``."""
        if not synchronous:
            return self.rospy.Publisher(topic, kind, queue_size=100, latch=latched)
        with warnings.catch_warnings():  # rospy warns about queue_size=None, which is meant here
            warnings.simplefilter("ignore", SyntaxWarning)
            return self.rospy.Publisher(topic, kind, queue_size=None, latch=latched)

    def subscriber(self, topic: str, kind: Any, callback: Callable[[Any], None], reliable: bool = True,
                   on_mismatch: Optional[Mismatch] = None, latched: bool = False) -> Any:
        """``rospy.Subscriber`` with a queue of 100 (a latched publisher's last message comes by itself)."""
        return self.rospy.Subscriber(topic, kind, callback, queue_size=100)

    def publisher_connections(self, pub: Any) -> int:
        """``get_num_connections``."""
        return int(pub.get_num_connections())

    def subscriber_connections(self, sub: Any) -> int:
        """``get_num_connections``."""
        return int(sub.get_num_connections())

    def topic_of(self, sub: Any) -> str:
        """``resolved_name``."""
        return str(sub.resolved_name)

    def unsubscribe(self, sub: Any) -> None:
        """``unregister``."""
        sub.unregister()

    def stamp(self, seconds: float) -> Any:
        """``rospy.Time.from_sec`` (truncated to nanoseconds)."""
        return self.rospy.Time.from_sec(seconds)

    def seconds(self, stamp: Any) -> float:
        """``to_sec``."""
        return float(stamp.to_sec())

    def now(self) -> Any:
        """``rospy.Time.now()``."""
        return self.rospy.Time.now()

    def set_use_sim_time(self) -> None:
        """The master's ``/use_sim_time`` parameter: nodes started after it follow ``/clock``."""
        self.rospy.set_param("/use_sim_time", True)

    def serialize(self, msg: Any) -> bytes:
        """genpy's ``serialize``."""
        import io

        buffer = io.BytesIO()
        msg.serialize(buffer)
        return buffer.getvalue()

    def schema(self, kind: Any) -> tuple[str, str, bytes]:
        """genpy's ``_type`` and ``_full_text`` (the definition with its dependencies, rosbag's format)."""
        return str(kind._type), "ros1msg", str(kind._full_text).encode()

    def ok(self) -> bool:
        """``not rospy.is_shutdown()``."""
        return not self.rospy.is_shutdown()

    def shutdown(self, reason: str) -> None:
        """``rospy.signal_shutdown``."""
        self.rospy.signal_shutdown(reason)
