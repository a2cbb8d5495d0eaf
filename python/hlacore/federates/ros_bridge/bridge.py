"""The ROS bridge: one ROS node (ROS 1 or ROS 2, :mod:`.ros_api`) and one HLA federate of the robot world's
federation in one process.

ROS → HLA: each :class:`TwistIn` subscribes a ``geometry_msgs/Twist`` topic and turns every message into a
``cmd_vel`` interaction (``linear.x``, ``angular.z``) for its robot. HLA → ROS: the ``WorldRobot``
reflections of the mapped robots are published as ``nav_msgs/Odometry`` (:class:`OdometryOut`, from the
``odometry`` or the ground-truth ``pose`` attribute), ``sensor_msgs/LaserScan`` (:class:`ScanOut`),
``sensor_msgs/Range`` (:class:`RangeOut`, the nearest beam) and ``std_msgs/Bool`` (:class:`StallOut`).

The other direction, for robots simulated by a ROS node (a stageros-style simulator,
:mod:`.stage_node`): HLA → ROS, each :class:`TwistOut` publishes the ``cmd_vel``
interactions naming its robot as ``geometry_msgs/Twist``; ROS → HLA, :class:`OdometryIn` (``odometry`` or
``pose``), :class:`ScanIn` and :class:`RangeIn` (``ranges``) and :class:`StallIn` (``stall``) become the
attributes of a ``WorldRobot`` instance that the bridge registers under the robot's name.

Threads: the ROS library calls the subscriber callbacks on its own threads (rospy: one per connection;
rclpy: one executor thread). The bridge's thread
(the one calling :meth:`RosBridge.spin`) is the only one that ticks the RTI, so the federate-ambassador
callbacks, and with them every ROS publication of a reflection, run there (``publish`` is
thread-safe in both). Untimed, a callback sends its interaction at once, in receive order, from ROS's thread
(hlacore's sends are thread-safe). Timed, callbacks only queue the commands; the bridge's thread sends
them after each grant ``G`` stamped ``G + lookahead`` (a send from another thread could race the
advance and break the sending rule).

Time: untimed (``timed=False``), the bridge is neither regulating nor constrained: commands apply from the
world's current step and reflections arrive in receive order, stamped with the node's ROS time (``now``). Timed, it
is regulating (``lookahead``) and constrained and advances by ``period`` (``timeAdvanceRequest(k *
period)``), optionally paced at ``rate`` federation seconds per wall second; reflections carry their
federation timestamp into ``header.stamp``; with ``clock=True`` it sets ``/use_sim_time`` and publishes
each grant on ``/clock`` (``rosgraph_msgs/Clock``), so that ROS time is federation time. With
``await_inputs`` (wall seconds) the bridge, after each grant at which it published something to ROS, waits
until every mapped Twist topic has spoken since the last grant (for ROS controllers that answer each
published state: a lockstep through ROS). With ``await_state`` (wall seconds) it waits, after publishing
each grant ``G`` on ``/clock``, until every stamped state topic (Odometry, LaserScan, Range) has a message
stamped ``G`` or later (for a simulator node that steps on ``/clock``), sends the state as updates stamped
``G + lookahead``, and only then publishes the ``cmd_vel`` interactions delivered with the grant.

The grid: the bridge requests ``k * period`` (like the world federate), except when it serves a simulator
node (``step_by_sum``, default: when it has state mappings), where it requests ``G + period``: with
``lookahead == period`` a federate answering a state stamped ``G + L`` with a command stamped ``(G + L) + L``
then hits a later grant exactly (``k * period`` would miss it by a rounding error now and then, and the
command would reach the node one period late).
"""

from __future__ import annotations

import functools
import math
import queue
import threading
import time as _time
from typing import Any, Optional, Sequence

import hlacore.rti as rti
from hlacore.federates.robot_world import codec

from .mappings import (
    Mapping,
    OdometryIn,
    OdometryOut,
    RangeIn,
    RangeOut,
    ScanIn,
    ScanOut,
    StallIn,
    StallOut,
    StateIn,
    TwistIn,
    TwistOut,
    node_mappings,
    stage_mappings,
    world_mappings,
    world_node_mappings,
)
from .ros_api import RosApi, reliable, yaw_of
from .recorder import TopicRecorder
from .said import Once
from .versions import select

__all__ = ["Mapping", "OdometryIn", "OdometryOut", "RangeIn", "RangeOut", "RosBridge", "ScanIn", "ScanOut",
           "StallIn", "StallOut", "StateIn", "TwistIn", "TwistOut", "node_mappings", "stage_mappings",
           "world_mappings", "world_node_mappings", "yaw_of"]


class _Ambassador(rti.FederateAmbassador):
    def __init__(self, bridge: "RosBridge") -> None:
        self.bridge = bridge
        self.names: dict[Any, str] = {}
        self.attributes: dict[Any, str] = {}
        self.parameters: dict[Any, str] = {}

    def discoverObjectInstance(self, obj: Any, cls: Any, name: str) -> None:
        """Note the discovered robot's name."""
        self.names[obj] = str(name)

    def removeObjectInstance(self, obj: Any, tag: Any, time: Any = None, retraction: Any = None) -> None:
        """Forget the removed robot."""
        self.names.pop(obj, None)

    def reflectAttributeValues(self, obj: Any, attributes: dict[Any, bytes], tag: Any, order: Any,
                               transport: Any, t: Optional[float] = None, retraction: Any = None) -> None:
        """Decode what a known robot reflects and hand it to the bridge, with its timestamp."""
        name = self.names.get(obj)
        if name is None:
            return
        kinds = {"pose": codec.POSE, "odometry": codec.ODOMETRY, "ranges": codec.RANGES, "stall": codec.STALL}
        values: dict[str, Any] = {}
        for handle, data in attributes.items():
            attr = self.attributes.get(handle)
            if attr in kinds:
                values[attr] = codec.unpack(kinds[attr], data)
        self.bridge._reflected(name, values, None if t is None else float(t))

    def receiveInteraction(self, cls: Any, parameters: dict[Any, bytes], tag: Any, order: Any, transport: Any,
                           t: Optional[float] = None, retraction: Any = None) -> None:
        """Hand a complete, decodable command to the bridge; count any other as ignored."""
        values = {self.parameters[h]: v for h, v in parameters.items() if h in self.parameters}
        if set(values) != set(codec.PARAMETERS):
            self.bridge.ignored += 1  # an incomplete command
            return
        try:
            robot = codec.unpack_name(values["robot"])
            linear = float(codec.unpack(codec.SPEED, values["linear"]))  # type: ignore[arg-type]
            angular = float(codec.unpack(codec.SPEED, values["angular"]))  # type: ignore[arg-type]
        except ValueError:
            self.bridge.ignored += 1  # undecodable: dropped, the bridge keeps serving
            return
        self.bridge._commanded(robot, linear, angular)


RETICK = 0.2  #: s between re-published ``/clock`` ticks while the bridge waits for the nodes' first state
WATCH = 0.5  #: s between looks at the subscribed topics' publishers (:meth:`RosBridge._watch`)
SILENCE = 2.0  #: s without a message after which an untimed bridge says a state topic went quiet


class RosBridge:
    """The bridge (see the module docstring). Build it, :meth:`start` it (init the ROS node, join the
    federation), :meth:`spin` on the thread that owns it until :meth:`stop`, then :meth:`close`."""

    def __init__(self, mappings: Sequence[Mapping], address: Optional[str] = None,
                 federation: str = codec.FEDERATION, federate_name: str = "ros_bridge",
                 node_name: str = "hla_bridge", timed: bool = True, period: float = 0.1,
                 lookahead: Optional[float] = None, clock: bool = False, rate: Optional[float] = None,
                 create: bool = True, await_inputs: Optional[float] = None,
                 await_state: Optional[float] = None, step_by_sum: Optional[bool] = None,
                 ros: Optional[RosApi] = None, record: Optional[str] = None) -> None:
        self.ros = ros if ros is not None else select()  #: the ROS side (ROS 1 or ROS 2)
        self.record = record  #: an MCAP file for every message bridged (:mod:`.recorder`), or None
        self.recorder: Optional[TopicRecorder] = None
        self.mappings = list(mappings)
        self.address = address
        self.federation = federation
        self.federate_name = federate_name
        self.node_name = node_name
        self.timed = timed
        self.period = float(period)
        self.lookahead = self.period if lookahead is None else float(lookahead)
        self.clock = clock
        self.rate = rate
        self.create = create
        self.await_inputs = await_inputs
        self.await_state = await_state
        self.step_by_sum = (any(isinstance(m, StateIn) for m in self.mappings) if step_by_sum is None
                            else step_by_sum)
        self.late_cycles = 0  #: timed grants after which ``await_inputs`` ran out before every Twist topic spoke
        self.late_states = 0  #: timed grants after which ``await_state`` ran out before every state topic spoke
        self.late_acks = 0  #: timed grants before which the nodes' Twist counts did not catch up in time
        self.updates = 0  #: WorldRobot updates sent from ROS state
        self.commands_out = 0  #: Twists published from cmd_vel interactions
        self.ignored = 0  #: cmd_vel interactions dropped (naming no TwistOut robot, or malformed)
        self.rejected = 0  #: ROS messages dropped for a non-finite value (a NaN velocity, a NaN pose)
        self.said = Once("ros_bridge")  #: what went wrong on the ROS side, said once each
        self.rtia: Optional[rti.RTIAmbassador] = None
        self.sent = 0  #: cmd_vel interactions sent
        self.published = 0  #: ROS messages published from reflections
        self.time = 0.0  #: the federate's time (the last grant)
        self._amb = _Ambassador(self)
        self._pending: "queue.SimpleQueue[tuple[str, float, float]]" = queue.SimpleQueue()
        self._stop = threading.Event()
        self._arrived: set[str] = set()
        self._published_before = 0
        self._inputs = threading.Condition()
        self._publishers: list[tuple[Mapping, Any]] = []
        self._subscribers: list[Any] = []
        self._velocity: dict[str, tuple[float, float]] = {}
        self._clock_pub: Any = None
        self._cmd: Any = None
        self._params: dict[str, Any] = {}
        self._twist_out: dict[str, list[Any]] = {}  # robot -> its TwistOut publishers
        self._acked: dict[str, int] = {}  # ack topic -> Twists published on its topic
        self._acks: dict[str, int] = {}  # ack topic -> the node's count
        self._ack_of: dict[int, str] = {}  # id(TwistOut publisher) -> its ack topic
        self._commands: list[tuple[str, float, float]] = []  # cmd_vel interactions to publish (timed)
        self._objects: dict[str, Any] = {}  # robot -> the WorldRobot instance the bridge registered
        self._handles: dict[str, Any] = {}  # attribute name -> handle
        self._state: dict[str, dict[str, bytes]] = {}  # robot -> attribute -> encoded value, not sent yet
        self._stamps: dict[str, float] = {}  # stamped state topic -> stamp of its latest message
        self._state_lock = threading.Condition()
        self._heard: dict[str, int] = {}  # subscribed topic -> publishers it heard at the last watch
        self._gone: set[str] = set()  # subscribed topics whose every publisher has left: not awaited
        self._silent: set[str] = set()  # state topics late once: not awaited until they speak again
        self._last_seen: dict[str, float] = {}  # subscribed topic -> monotonic time of its last message
        self._next_watch = 0.0
        self._topic_of: dict[int, str] = {}  # id(TwistOut publisher) -> its topic
        if self.timed and not self.lookahead > 0:
            raise ValueError("lookahead must be positive")

    # ---- life cycle ----

    def start(self, master_timeout: float = 10.0, timeout: float = 10.0) -> None:
        """Init the ROS node (once per process; ROS 1: the master must answer within ``master_timeout`` s),
        join the federation (creating it from the robot world's FOM when ``create``), enable time
        management when timed, then advertise and subscribe the ROS topics, each with the QoS of the HLA
        transport of what it carries (:func:`.ros_api.reliable`)."""
        ros, msgs = self.ros, self.ros.msgs
        ros.init_node(self.node_name, master_timeout, sim_time=self.clock)
        if self.record is not None:
            self.recorder = TopicRecorder(self.record, ros)
        if self.clock:
            ros.set_use_sim_time()
            self._clock_pub = ros.publisher("/clock", msgs.Clock)
        kinds = {OdometryOut: msgs.Odometry, ScanOut: msgs.LaserScan, RangeOut: msgs.Range, StallOut: msgs.Bool}
        for m in self.mappings:
            if isinstance(m, (OdometryOut, ScanOut, RangeOut, StallOut)):
                self._publishers.append((m, ros.publisher(m.topic, kinds[type(m)], reliable(_attribute(m)))))
            elif isinstance(m, TwistOut):
                # synchronous: publish() has written before it returns, so a Twist leaves before the next /clock
                pub = ros.publisher(m.topic, msgs.Twist, reliable(codec.INTERACTION), synchronous=True)
                self._publishers.append((m, pub))
                self._twist_out.setdefault(m.robot, []).append(pub)
                self._topic_of[id(pub)] = m.topic
                if m.ack is not None:
                    self._ack_of[id(pub)] = m.ack
                    self._acked[m.ack] = self._acks[m.ack] = 0

        rtia = rti.RTIAmbassador(self.address)
        fom = str(codec.FOM_PATH) if self.create else None
        rtia.create_or_join(self.federate_name, self.federation, fom, self._amb)
        self.rtia = rtia
        try:
            robot = rtia.getObjectClassHandle(codec.OBJECT_CLASS)
            self._amb.attributes = {rtia.getAttributeHandle(n, robot): n for n in codec.ATTRIBUTES}
            rtia.subscribeObjectClassAttributes(robot, list(self._amb.attributes))
            self._cmd = rtia.getInteractionClassHandle(codec.INTERACTION)
            self._params = {n: rtia.getParameterHandle(n, self._cmd) for n in codec.PARAMETERS}
            rtia.publishInteractionClass(self._cmd)
            if self._twist_out:
                self._amb.parameters = {h: n for n, h in self._params.items()}
                rtia.subscribeInteractionClass(self._cmd)
            if self.timed:
                self.time = rtia.enable_time_management(self.lookahead, timeout)
            # registered once time is enabled: a federate that discovers them knows the bridge regulates
            state_robots = list(dict.fromkeys(m.robot for m in self.mappings if isinstance(m, StateIn)))
            if state_robots:
                self._handles = {n: h for h, n in self._amb.attributes.items()}
                rtia.publishObjectClass(robot, list(self._amb.attributes))
                for name in state_robots:
                    self._objects[name] = rtia.registerObjectInstance(robot, name)
                    if self.timed:
                        self._state[name] = {"name": codec.NAME.pack(name)}  # sent with the first state
                    else:
                        rtia.updateAttributeValues(self._objects[name],
                                                   {self._handles["name"]: codec.NAME.pack(name)}, "ros")
        except BaseException:
            rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            self.rtia = None
            raise
        state_kinds = {OdometryIn: msgs.Odometry, ScanIn: msgs.LaserScan, RangeIn: msgs.Range, StallIn: msgs.Bool}
        for m in self.mappings:
            if isinstance(m, TwistIn):
                self._subscribers.append(ros.subscriber(m.topic, msgs.Twist, functools.partial(self._on_twist,
                                                        robot=m.robot, topic=m.topic),
                                                        reliable(codec.INTERACTION), self._mismatch))
            elif isinstance(m, (OdometryIn, ScanIn, RangeIn, StallIn)):
                self._subscribers.append(ros.subscriber(m.topic, state_kinds[type(m)],
                                                        functools.partial(self._on_state, m=m),
                                                        reliable(_attribute(m)), self._mismatch))
            elif isinstance(m, TwistOut) and m.ack is not None:
                self._subscribers.append(ros.subscriber(m.ack, msgs.UInt32, functools.partial(self._on_ack,
                                                        ack=m.ack), True, self._mismatch, latched=True))

    def spin(self, until: Optional[float] = None, cycle_timeout: float = 0.05) -> float:
        """Run the bridge on this thread until :meth:`stop` (or, timed, federation time ``until``); returns
        the federate's time. Timed: one ``timeAdvanceRequest`` per period, waiting for each grant in slices
        of ``cycle_timeout`` s so that a stop is seen. Untimed: ticks."""
        rtia = self._rtia()
        if not self.timed:
            while not self._stop.is_set() and self.ros.ok():
                rtia.tick(0.01, cycle_timeout)
                self._watch()
            return self.time
        wall0, fed0 = _time.monotonic(), self.time
        k = round(self.time / self.period)
        if self._objects:  # the node's initial state, as the world federate publishes its own at 0 + L
            # Re-ticked until every state topic has spoken: a rospy subscriber counts its connection before
            # the node's publisher has added it (a DDS reader can match before the writer does), so the
            # node's first messages can be lost.
            self._tick_clock()
            self._sync_state(retick=True)
        while not self._stop.is_set() and self.ros.ok():
            self._watch()
            if until is not None and self.time >= until - 1e-9:
                break
            k += 1
            # by sums when serving a node: a reply stamped (G + L) + L is then exactly a later grant
            rtia.timeAdvanceRequest(self.time + self.period if self.step_by_sum else k * self.period)
            while True:
                try:
                    self.time = rtia.await_grant(cycle_timeout)
                    break
                except TimeoutError:
                    if self._stop.is_set() or not self.ros.ok():
                        return self.time
                    self._watch()  # the federation may be held by another federate: still say what ROS does
            self._granted()
            if self.rate:
                delay = wall0 + (self.time - fed0) / self.rate - _time.monotonic()
                if delay > 0:
                    self._stop.wait(delay)
        return self.time

    def connections(self) -> dict[str, int]:
        """The number of ROS connections of each bridged topic (publishers' subscribers, subscribers'
        publishers): to wait until the nodes on the other side are wired before spinning."""
        ros = self.ros
        out = {m.topic: ros.publisher_connections(pub) for m, pub in self._publishers}
        for sub in self._subscribers:
            out[ros.topic_of(sub)] = ros.subscriber_connections(sub)
        if self._clock_pub is not None:
            out["/clock"] = ros.publisher_connections(self._clock_pub)
        return out

    def wait_connected(self, timeout: float, topics: Optional[Sequence[str]] = None) -> None:
        """Wait until each of ``topics`` (default: every bridged topic, and ``/clock`` for the nodes that
        follow it when the bridge publishes it) has a connection; TimeoutError names the unconnected ones."""
        deadline = _time.monotonic() + timeout
        while True:
            seen = self.connections()
            missing = [t for t in (seen if topics is None else topics) if seen.get(t, 0) == 0]
            if not missing:
                return
            if _time.monotonic() > deadline:
                raise TimeoutError(f"no ROS connection within {timeout} s on {missing}")
            self._stop.wait(0.05)

    def stop(self) -> None:
        """Ask :meth:`spin` to return (safe from any thread and from a signal handler)."""
        self._stop.set()

    def close(self, reason: str = "bridge closed") -> None:
        """Unsubscribe, resign (deleting nothing: the bridge owns no object), and shut the ROS node down."""
        for sub in self._subscribers:
            self.ros.unsubscribe(sub)
        self._subscribers.clear()
        if self.rtia is not None:
            self.rtia.resignFederationExecution(rti.ResignAction.DeleteObjectsAndReleaseAttributes)
            self.rtia = None
        self.ros.shutdown(reason)
        if self.recorder is not None:
            self.recorder.close()

    # ---- ROS → HLA ----

    def _on_twist(self, msg: Any, robot: str, topic: str) -> None:
        """ROS's thread: untimed, send now (receive order); timed, queue for the bridge's thread. A
        non-finite velocity is dropped (said once per topic): NaN would poison the world's physics."""
        self._recorded(topic, msg)
        linear, angular = float(msg.linear.x), float(msg.angular.z)
        self._last_seen[topic] = _time.monotonic()
        if not (math.isfinite(linear) and math.isfinite(angular)):
            self._reject(topic, f"a Twist with a non-finite velocity (linear.x {linear}, angular.z {angular})")
            return
        if self.timed:
            with self._inputs:
                self._pending.put((robot, linear, angular))
                self._arrived.add(robot)
                self._inputs.notify_all()
        elif self.rtia is not None:
            self._send(robot, linear, angular, None)

    def _send(self, robot: str, linear: float, angular: float, stamp: Optional[float]) -> None:
        p = self._params
        values = {p["robot"]: codec.NAME.pack(robot), p["linear"]: codec.SPEED.pack(linear),
                  p["angular"]: codec.SPEED.pack(angular)}
        rtia = self._rtia()
        if stamp is None:
            rtia.sendInteraction(self._cmd, values, "ros")
        else:
            rtia.sendInteraction(self._cmd, values, "ros", stamp)
        self.sent += 1

    def _granted(self) -> None:
        """After a grant, on the bridge's thread: /clock, the nodes' state stamped G + lookahead, the cmd_vel
        interactions delivered with the grant as Twists, then the queued commands stamped G + lookahead."""
        self._await_acks()
        self._tick_clock()
        if self._objects:
            self._sync_state()
        self._publish_commands()
        if self.await_inputs is not None and self.published > self._published_before:
            wanted = {m.robot for m in self.mappings if isinstance(m, TwistIn)}
            with self._inputs:
                if not self._inputs.wait_for(lambda: wanted <= self._arrived or self._stop.is_set(),
                                             self.await_inputs):
                    self.late_cycles += 1
                self._arrived.clear()
        self._published_before = self.published
        while True:
            try:
                robot, linear, angular = self._pending.get_nowait()
            except queue.Empty:
                break
            self._send(robot, linear, angular, self.time + self.lookahead)

    def _on_state(self, msg: Any, m: Mapping) -> None:
        """ROS's thread: a robot's state from a simulator node; untimed, sent at once (receive order);
        timed, kept (the latest value of each attribute wins) until the bridge's thread sends it. An
        Odometry with a non-finite value is dropped (said once per topic); ranges keep inf and NaN (REP 117:
        out of range, no reading)."""
        topic = getattr(m, "topic")
        self._recorded(topic, msg)
        self._last_seen[topic] = _time.monotonic()
        if isinstance(m, OdometryIn):
            p, q, t = msg.pose.pose.position, msg.pose.pose.orientation, msg.twist.twist
            values = [float(p.x), float(p.y), yaw_of(q), float(t.linear.x), float(t.angular.z)]
            if not all(math.isfinite(v) for v in values):
                self._reject(topic, f"an Odometry with a non-finite value ({values})")
                return
            value = codec.POSE.pack(values[:3]) if m.attribute == "pose" else codec.ODOMETRY.pack(values)
            attribute = m.attribute
        elif isinstance(m, ScanIn):
            value, attribute = codec.RANGES.pack([float(r) for r in msg.ranges]), "ranges"
        elif isinstance(m, RangeIn):
            value, attribute = codec.RANGES.pack([float(msg.range)]), "ranges"
        else:
            value, attribute = codec.STALL.pack(bool(msg.data)), "stall"
        robot = getattr(m, "robot")
        if not self.timed:
            if self.rtia is not None:
                self.rtia.updateAttributeValues(self._objects[robot], {self._handles[attribute]: value}, "ros")
                self.updates += 1
            return
        with self._state_lock:
            self._state.setdefault(robot, {})[attribute] = value
            self._silent.discard(topic)
            if hasattr(msg, "header"):
                self._stamps[topic] = self.ros.seconds(msg.header.stamp)
            self._state_lock.notify_all()

    def _sync_state(self, retick: bool = False) -> None:
        """Timed, on the bridge's thread at time ``G``: with ``await_state``, wait until every stamped state
        topic has a message stamped ``G`` or later; then send each robot's new values stamped ``G + L``.
        ``retick``: publish ``/clock`` again every :data:`RETICK` s while waiting (the first state, see
        :meth:`spin`)."""
        if self.await_state is not None:
            topics = [m.topic for m in self.mappings if isinstance(m, (OdometryIn, ScanIn, RangeIn))]
            fresh = self.time - 2e-9 - 1e-9 * abs(self.time)  # ROS stamps are truncated to nanoseconds

            def awaited() -> list[str]:  # a topic whose node has died, or stopped answering, is not awaited
                return [t for t in topics if t not in self._gone and t not in self._silent]

            def arrived() -> bool:
                return self._stop.is_set() or all(self._stamps.get(t, -math.inf) >= fresh for t in awaited())

            deadline = _time.monotonic() + self.await_state
            while True:
                left = deadline - _time.monotonic()
                with self._state_lock:
                    if self._state_lock.wait_for(arrived, max(0.0, min(left, RETICK if retick else WATCH))):
                        break
                    if _time.monotonic() >= deadline:
                        self.late_states += 1
                        stale = {t: self._stamps.get(t) for t in awaited() if self._stamps.get(t, -math.inf) < fresh}
                        self._silent.update(stale)  # awaited again once they speak (_on_state)
                        self.said.say(("late", tuple(sorted(stale))),
                                      f"late state at {self.time!r}: nothing stamped {self.time!r} within "
                                      f"{self.await_state} s on {stale}; not awaited until they speak again")
                        break
                if retick:
                    self._tick_clock()  # a tick at the node's own time only re-publishes its state
                self._watch()
        with self._state_lock:
            pending, self._state = self._state, {}
        rtia = self._rtia()
        for robot, values in pending.items():
            if values:
                rtia.updateAttributeValues(self._objects[robot], {self._handles[a]: v for a, v in values.items()},
                                           "ros", self.time + self.lookahead)
                self.updates += 1

    def _commanded(self, robot: str, linear: float, angular: float) -> None:
        """The bridge's thread (a cmd_vel interaction): untimed, publish at once; timed, after the grant."""
        if robot not in self._twist_out:
            self.ignored += 1
            return
        self._commands.append((robot, linear, angular))
        if not self.timed:
            self._publish_commands()

    def _publish_commands(self) -> None:
        commands, self._commands = self._commands, []
        for robot, linear, angular in commands:
            msg = self.ros.msgs.Twist()
            msg.linear.x, msg.angular.z = linear, angular
            for pub in self._twist_out[robot]:
                pub.publish(msg)
                self._recorded(self._topic_of[id(pub)], msg)
                self.commands_out += 1
                ack = self._ack_of.get(id(pub))
                if ack is not None:
                    with self._state_lock:
                        self._acked[ack] += 1

    def _on_ack(self, msg: Any, ack: str) -> None:
        """ROS's thread: the node's count of the Twists it took."""
        self._recorded(ack, msg)
        with self._state_lock:
            self._acks[ack] = int(msg.data)
            self._state_lock.notify_all()

    def _await_acks(self) -> None:
        """Timed, before the next /clock: wait (``await_state`` s at most) until every acknowledging node
        has taken every Twist published to it."""
        if not self._acked:
            return

        def caught_up() -> bool:  # a node that has died acknowledges nothing: not awaited
            return self._stop.is_set() or all(self._acks[a] >= n for a, n in self._acked.items()
                                               if a not in self._gone)

        deadline = _time.monotonic() + (self.await_state or 5.0)
        while True:
            with self._state_lock:
                if self._state_lock.wait_for(caught_up, max(0.0, min(WATCH, deadline - _time.monotonic()))):
                    return
                if _time.monotonic() >= deadline:
                    self.late_acks += 1
                    behind = {a: (self._acks[a], n) for a, n in self._acked.items() if self._acks[a] < n}
                    for a in behind:  # the missing counts are not awaited again
                        self._acked[a] = self._acks[a]
                    self.said.say(("late acks", tuple(sorted(behind))),
                                  f"late acknowledgement before {self.time!r}: (taken, published) {behind}")
                    return
            self._watch()

    def _tick_clock(self) -> None:
        if self._clock_pub is not None:
            tick = self.ros.clock(self.time)
            self._clock_pub.publish(tick)
            self._recorded("/clock", tick)

    # ---- HLA → ROS ----

    def _reflected(self, robot: str, values: dict[str, Any], stamp: Optional[float]) -> None:
        odom = values.get("odometry")
        if odom is not None:
            self._velocity[robot] = (float(odom[3]), float(odom[4]))
        when = self.ros.now() if stamp is None else self.ros.stamp(stamp)
        for m, pub in self._publishers:
            if m.robot != robot or isinstance(m, TwistOut):
                continue
            msg = self._message(m, values, when)
            if msg is not None:
                pub.publish(msg)
                self._recorded(m.topic, msg)
                self.published += 1

    def _message(self, m: Mapping, values: dict[str, Any], when: Any) -> Any:
        msgs = self.ros.msgs
        if isinstance(m, OdometryOut):
            data = values.get(m.source)
            if data is None:
                return None
            msg = msgs.Odometry()
            msg.header.stamp = when
            msg.header.frame_id = m.frame_id
            msg.child_frame_id = m.child_frame_id
            msg.pose.pose.position.x, msg.pose.pose.position.y = float(data[0]), float(data[1])
            msg.pose.pose.orientation = self.ros.quaternion(float(data[2]))
            v, w = self._velocity.get(m.robot, (0.0, 0.0))
            msg.twist.twist.linear.x, msg.twist.twist.angular.z = v, w
            return msg
        if isinstance(m, StallOut):
            stall = values.get("stall")
            return None if stall is None else msgs.Bool(data=bool(stall))
        ranges = values.get("ranges")
        if ranges is None or len(ranges) == 0:
            return None
        if isinstance(m, ScanOut):
            msg = msgs.LaserScan()
            msg.header.stamp = when
            msg.header.frame_id = m.frame_id
            n = len(ranges)
            msg.angle_min, msg.angle_max = (-m.fov / 2, m.fov / 2) if n > 1 else (0.0, 0.0)
            msg.angle_increment = m.fov / (n - 1) if n > 1 else 0.0
            msg.range_min, msg.range_max = float(m.range_min), float(m.range_max)
            msg.ranges = [float(r) for r in ranges]
            return msg
        assert isinstance(m, RangeOut), m
        msg = msgs.Range()
        msg.header.stamp = when
        msg.header.frame_id = m.frame_id
        msg.radiation_type = msgs.Range.ULTRASOUND
        msg.field_of_view = float(m.fov)
        msg.min_range, msg.max_range = float(m.range_min), float(m.range_max)
        msg.range = float(min(ranges))
        return msg

    # ---- what goes wrong on the ROS side: said once, the federation goes on ----

    def _watch(self) -> None:
        """On the bridge's thread, every :data:`WATCH` s: a subscribed topic that has lost every publisher
        (its node died or left) is said once and no longer awaited, until a publisher is back; a publisher of
        another type on a subscribed topic is said once; untimed, a state topic silent for :data:`SILENCE` s
        while its publisher is still there is said once."""
        now = _time.monotonic()
        if now < self._next_watch:
            return
        self._next_watch = now + WATCH
        states = {m.topic for m in self.mappings if isinstance(m, (OdometryIn, ScanIn, RangeIn, StallIn))}
        for sub in self._subscribers:
            topic = self.ros.topic_of(sub)
            count = self.ros.subscriber_connections(sub)
            if count == 0 and self._heard.get(topic, 0) > 0:
                self._gone.add(topic)
                self.said.say(("gone", topic), f"no publisher left on {topic}: its node died or left; "
                                               "the federation goes on without it")
            elif count > 0 and topic in self._gone:
                self._gone.discard(topic)
                self.said.forget(("gone", topic))
                self.said.say(("back", topic), f"a publisher is back on {topic}")
            self._heard[topic] = count
            for other in self.ros.foreign_publishers(sub):
                self._mismatch(topic, f"a publisher of {other} (the bridge reads another type there)")
            seen = self._last_seen.get(topic)
            if not self.timed and topic in states and count > 0 and seen is not None:
                if now - seen > SILENCE:
                    self.said.say(("silent", topic), f"nothing on {topic} for {SILENCE} s: its node stopped "
                                                     "publishing; the federation goes on")
                else:
                    self.said.forget(("silent", topic))

    def _reject(self, topic: str, what: str) -> None:
        self.rejected += 1
        self.said.say(("rejected", topic), f"dropped {what} on {topic} (said once; counted as rejected)")

    def _mismatch(self, topic: str, what: str) -> None:
        self.said.say(("mismatch", topic, what), f"{topic}: {what}; its messages are not bridged")

    # ---- helpers ----

    def _recorded(self, topic: str, msg: Any) -> None:
        if self.recorder is not None:
            self.recorder.record(topic, msg)

    def _rtia(self) -> rti.RTIAmbassador:
        if self.rtia is None:
            raise RuntimeError("the bridge is not started")
        return self.rtia


def _attribute(m: Mapping) -> str:
    """The ``WorldRobot`` attribute a state mapping carries (its topic's QoS follows that attribute's
    transport)."""
    if isinstance(m, (OdometryIn, OdometryOut)):
        return m.attribute if isinstance(m, OdometryIn) else m.source
    if isinstance(m, (StallIn, StallOut)):
        return "stall"
    return "ranges"
