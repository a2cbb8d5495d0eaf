""":class:`~.ros_api.RosApi` on ROS 2: rclpy over Fast DDS, from ROS 2 Kilted's wheels (:mod:`.ros2_env`).

The process must have been started with :func:`.ros2_env.environment` (or a sourced ROS 2 install): the
dynamic loader reads the library path only at start.
"""

from __future__ import annotations

import threading
from typing import Any, Callable, Optional

from .ros2_env import INSTALL_HINT
from .ros_api import Messages, Mismatch, RosApi

#: Depth of every topic's history (KEEP_LAST): as rospy's queues of 100, enough for a lockstep's bursts.
DEPTH = 100


class Ros2(RosApi):
    """rclpy: one node in a context of its own, its callbacks run by a single-threaded executor on a thread
    of its own (so they never run concurrently with each other). QoS: reliable, or best effort (the
    sensor-data profile's), KEEP_LAST :data:`DEPTH`, volatile. rclpy's signal handlers are not installed:
    the commands keep their own SIGTERM / SIGINT handling."""

    version = 2
    message_encoding = "cdr"

    def __init__(self) -> None:
        try:
            import rclpy
            from geometry_msgs.msg import Quaternion, Twist
            from nav_msgs.msg import Odometry
            from rosgraph_msgs.msg import Clock
            from sensor_msgs.msg import LaserScan, Range
            from std_msgs.msg import Bool, UInt32
        except ImportError as error:
            raise ImportError(f"{INSTALL_HINT}; start the process with "
                              f"hlacore.federates.ros_bridge.ros2_env.environment() ({error})") from error
        self.rclpy = rclpy
        self.msgs = Messages(Twist, Quaternion, Odometry, Clock, LaserScan, Range, Bool, UInt32)
        self.context = rclpy.Context()
        self.node: Any = None
        self._executor: Any = None
        self._thread: Optional[threading.Thread] = None

    def init_node(self, name: str, timeout: float = 10.0, sim_time: bool = False) -> None:
        """``rclpy.init`` (no signal handlers) and the node, ``use_sim_time`` = ``sim_time``; its executor
        starts on a thread named ``rclpy``."""
        from rclpy.executors import SingleThreadedExecutor
        from rclpy.parameter import Parameter
        from rclpy.signals import SignalHandlerOptions

        self.rclpy.init(context=self.context, signal_handler_options=SignalHandlerOptions.NO)
        self.node = self.rclpy.create_node(name, context=self.context,
                                           parameter_overrides=[Parameter("use_sim_time", value=sim_time)])
        self._executor = SingleThreadedExecutor(context=self.context)
        self._executor.add_node(self.node)
        self._thread = threading.Thread(target=self._spin, name="rclpy", daemon=True)
        self._thread.start()

    def _spin(self) -> None:
        from rclpy.executors import ExternalShutdownException

        try:
            while self.context.ok():
                self._executor.spin_once(timeout_sec=0.1)
        except ExternalShutdownException:
            pass

    def _qos(self, reliable: bool, latched: bool = False) -> Any:
        from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy

        durability = DurabilityPolicy.TRANSIENT_LOCAL if latched else DurabilityPolicy.VOLATILE
        return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=DEPTH, durability=durability,
                          reliability=ReliabilityPolicy.RELIABLE if reliable else ReliabilityPolicy.BEST_EFFORT)

    def publisher(self, topic: str, kind: Any, reliable: bool = True, synchronous: bool = False,
                  latched: bool = False) -> Any:
        """``create_publisher`` with the QoS of ``reliable`` and ``latched`` (``synchronous``: Fast DDS
        publishes synchronously in any case, :mod:`.ros2_env` sets ``RMW_FASTRTPS_PUBLICATION_MODE``)."""
        return self.node.create_publisher(kind, topic, self._qos(reliable, latched))

    def subscriber(self, topic: str, kind: Any, callback: Callable[[Any], None], reliable: bool = True,
                   on_mismatch: Optional[Mismatch] = None, latched: bool = False) -> Any:
        """``create_subscription``; the middleware's incompatible-QoS event goes to ``on_mismatch`` with the
        policy that does not match."""
        from rclpy.event_handler import SubscriptionEventCallbacks

        events = None
        if on_mismatch is not None:
            def wrong_qos(info: Any) -> None:
                on_mismatch(topic, f"a publisher whose QoS does not match ({info.last_policy_kind.name}; "
                                   f"this subscription is {'reliable' if reliable else 'best effort'})")

            # Fast DDS does not raise the incompatible-type event (seen with these wheels): the bridge looks
            # at the graph instead (foreign_publishers)
            events = SubscriptionEventCallbacks(incompatible_qos=wrong_qos)
        return self.node.create_subscription(kind, topic, callback, self._qos(reliable, latched),
                                             event_callbacks=events)

    def foreign_publishers(self, sub: Any) -> list[str]:
        """From the ROS graph: the types of the publishers on the topic other than the subscription's."""
        ours = type_name(sub.msg_type)
        return sorted({i.topic_type for i in self.node.get_publishers_info_by_topic(sub.topic_name)} - {ours})

    def publisher_connections(self, pub: Any) -> int:
        """``get_subscription_count``: the matched subscriptions."""
        return int(pub.get_subscription_count())

    def subscriber_connections(self, sub: Any) -> int:
        """``get_publisher_count``: the matched publishers."""
        return int(sub.get_publisher_count())

    def topic_of(self, sub: Any) -> str:
        """``topic_name``."""
        return str(sub.topic_name)

    def unsubscribe(self, sub: Any) -> None:
        """``destroy_subscription``."""
        self.node.destroy_subscription(sub)

    def stamp(self, seconds: float) -> Any:
        """``builtin_interfaces/Time`` of ``seconds`` rounded to whole nanoseconds."""
        from builtin_interfaces.msg import Time

        ns = round(seconds * 1e9)
        return Time(sec=ns // 1_000_000_000, nanosec=ns % 1_000_000_000)

    def seconds(self, stamp: Any) -> float:
        """``sec + nanosec / 1e9``."""
        return int(stamp.sec) + int(stamp.nanosec) * 1e-9

    def now(self) -> Any:
        """The node's clock (``/clock`` when ``use_sim_time``), as a message."""
        return self.node.get_clock().now().to_msg()

    def set_use_sim_time(self) -> None:
        """This node's ``use_sim_time`` parameter (ROS 2 has no global one)."""
        from rclpy.parameter import Parameter

        self.node.set_parameters([Parameter("use_sim_time", value=True)])

    def serialize(self, msg: Any) -> bytes:
        """``rclpy.serialization.serialize_message``: CDR, as DDS carries it."""
        from rclpy.serialization import serialize_message

        return bytes(serialize_message(msg))

    def schema(self, kind: Any) -> tuple[str, str, bytes]:
        """``ros2msg``: the ``.msg`` files of the type and of every type it uses, from the packages' share
        directories (the ament index), each after a line of ``=`` and ``MSG: pkg/Type``, as rosbag2 writes."""
        from ament_index_python.packages import get_package_share_directory

        def text(name: str) -> str:
            package, _, type_ = name.partition("/")
            path = f"{get_package_share_directory(package)}/msg/{type_}.msg"
            with open(path, encoding="utf-8") as f:
                return f.read()

        name = type_name(kind).replace("/msg/", "/")
        parts, seen, todo = [], {name}, [name]
        while todo:
            current = todo.pop(0)
            definition = text(current)
            parts.append(definition if current == name else f"{'=' * 80}\nMSG: {current}\n{definition}")
            for used in msg_dependencies(definition, current.split("/")[0]):
                if used not in seen:
                    seen.add(used)
                    todo.append(used)
        return name, "ros2msg", "\n".join(parts).encode()

    def ok(self) -> bool:
        """Whether the node's context is up."""
        return bool(self.context.ok())

    def shutdown(self, reason: str) -> None:
        """Shut the context down (the executor's thread returns), then destroy the node."""
        if self.node is None:
            return
        self.context.try_shutdown()
        if self._thread is not None:
            self._thread.join(5.0)
        self.node.destroy_node()
        self.node = None


def type_name(kind: Any) -> str:
    """A ROS 2 message class's type name, as the graph reports it: ``geometry_msgs/msg/Twist``."""
    return f"{kind.__module__.split('.')[0]}/msg/{kind.__name__}"


PRIMITIVES = frozenset({"bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16", "int32",
                        "uint32", "int64", "uint64", "string", "wstring"})


def msg_dependencies(definition: str, package: str) -> list[str]:
    """The message types (``pkg/Type``) a ``.msg`` definition's fields use, in order (``package``: the
    definition's own, for unqualified names)."""
    found: list[str] = []
    for line in definition.splitlines():
        words = line.split("#", 1)[0].split()
        if len(words) < 2:
            continue
        base = words[0].split("[", 1)[0].split("<=", 1)[0]
        if base in PRIMITIVES:
            continue
        qualified = base.replace("/msg/", "/") if "/" in base else f"{package}/{base}"
        if qualified not in found:
            found.append(qualified)
    return found
