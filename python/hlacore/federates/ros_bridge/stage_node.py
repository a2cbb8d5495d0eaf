"""The robot world as a stageros-style ROS node: Stage's role in paper 1 (ros-ptolemy-hla-iess2015), with
the HLA side reached through the ROS bridge (``--world-node``). It lives with the bridge because it is ROS
code (:class:`~.ros_api.RosApi`, ROS 1 or ROS 2); the robot world itself knows nothing of ROS.

    python -m hlacore.federates.ros_bridge.stage_node WORLD [--ros 1|2] [--dt 0.01] [--watchdog 0.2]
        [--rate R] [--summary FILE.json] [--snapshot FILE.png] [--until T]

``--ros`` as the bridge's (default: ``ros_api.detect``); on ROS 2 the node's topics are reliable, as the
robot world's FOM declares every ``WorldRobot`` attribute, and the node's own clock follows ``/clock``
(``use_sim_time``).

Topics, per robot (named by the world file's ``name``, else ``robot_<index>``, as stageros with ``-u``):

* in: ``/<robot>/cmd_vel`` (``geometry_msgs/Twist``: ``linear.x``, ``angular.z``), applied from the next
  physics step, as stageros' ``SetSpeed`` (clipped to the robot's bounds; a non-finite one is rejected,
  counted and logged once, and the robot keeps its previous command);
* out, once per clock tick, stamped with it: ``/<robot>/odom`` (``nav_msgs/Odometry``: integrated
  odometry, with the applied velocities in the twist), ``/<robot>/base_pose_ground_truth`` (ground truth),
  ``/<robot>/base_scan`` (``sensor_msgs/LaserScan``: every beam of the robot's rangers) and our own
  ``/<robot>/range`` (``sensor_msgs/Range``, the nearest beam) and ``/<robot>/stall`` (``std_msgs/Bool``);
* out, after each Twist taken (applied or rejected), ours: ``/<robot>/cmd_vel_received`` (``std_msgs/UInt32``,
  how many so far; latched, so that a count sent while the bridge's connection is still being made is not
  lost), so that a bridge can hold the next clock tick until the node has its commands.

Pacing. By default the node has no clock of its own: it follows ``/clock`` (ROS time with
``use_sim_time``, published by the ROS bridge at every federation grant). Each tick ``t`` steps the world
by whole ``dt`` steps up to ``t`` (the last grid point at or before it), then publishes every robot's state
stamped ``t``; a tick at or before the world's time only re-publishes. Nothing reads the wall clock, so the
node is as deterministic as the world: the same commands between the same ticks give the same states.
With ``--rate R`` it runs like stageros instead: it steps ``interval_sim`` of the world file every
``interval_sim / R`` wall seconds, publishes ``/clock`` itself and sets ``/use_sim_time``.

SIGTERM or SIGINT stops it; it then writes the ``--summary`` JSON (every tick's time and poses, the stall
counts, the commands received) and the ``--snapshot`` PNG.
"""

from __future__ import annotations

import argparse
import functools
import json
import math
import signal
import sys
import threading
import time as _time
from typing import Any, Optional, Sequence

from hlacore.federates.robot_world.render import trajectories, write_labelled_snapshot
from hlacore.federates.robot_world.world import Pose, World
from hlacore.federates.robot_world.worldfile import read_world

from . import ros2_env
from .ros_api import RosApi
from .versions import detect, select


class StageNode:
    """A :class:`World` behind stageros' topics (see the module docstring). Build it, :meth:`start` it
    (the ROS node, once per process), let the ROS library's threads drive it, :meth:`close` it."""

    def __init__(self, world: World, node_name: str = "stage", ros: Optional[RosApi] = None) -> None:
        self.world = world
        self.ros = ros if ros is not None else select()  #: the ROS side (ROS 1 or ROS 2)
        self.node_name = node_name
        self.lock = threading.Lock()  # rospy calls back on one thread per connection
        #: (world time, poses) after every tick that stepped (the world time is the tick on the step grid)
        self.history: list[tuple[float, dict[str, Pose]]] = []
        self.commands = 0  #: cmd_vel messages applied
        self.rejected = 0  #: cmd_vel messages rejected (non-finite velocities)
        self.ticks = 0  #: clock ticks handled
        self.time = world.time  #: the last tick
        self._pubs: dict[str, dict[str, Any]] = {}
        self._received: dict[str, int] = {}  # robot -> Twists taken
        self._subs: list[Any] = []
        self._started = False

    def start(self, follow_clock: bool = True) -> None:
        """Init the ROS node, advertise every robot's topics, subscribe its ``cmd_vel`` (and ``/clock`` when
        ``follow_clock``)."""
        ros, msgs = self.ros, self.ros.msgs
        ros.init_node(self.node_name, sim_time=follow_clock)
        self._started = True
        kinds = {"odom": msgs.Odometry, "base_pose_ground_truth": msgs.Odometry, "base_scan": msgs.LaserScan,
                 "range": msgs.Range, "stall": msgs.Bool, "cmd_vel_received": msgs.UInt32}
        for robot in self.world.robots:
            # the acknowledgements latched: the first, sent perhaps before the bridge's connection is complete, is
            # not lost (the bridge would wait for it in vain)
            self._pubs[robot.name] = {t: ros.publisher(f"/{robot.name}/{t}", k, latched=t == "cmd_vel_received")
                                      for t, k in kinds.items()}
            self._received[robot.name] = 0
            self._subs.append(ros.subscriber(f"/{robot.name}/cmd_vel", msgs.Twist,
                                             functools.partial(self._on_cmd, robot=robot.name)))
        if follow_clock:
            self._subs.append(ros.subscriber("/clock", msgs.Clock, self._on_clock))

    def close(self) -> None:
        """Unsubscribe and shut the ROS node down."""
        for sub in self._subs:
            self.ros.unsubscribe(sub)
        self._subs.clear()
        if self._started:
            self.ros.shutdown("stage node closed")

    # ---- the world's side ----

    def _on_cmd(self, msg: Any, robot: str) -> None:
        linear, angular = float(msg.linear.x), float(msg.angular.z)
        with self.lock:
            if math.isfinite(linear) and math.isfinite(angular):
                self.world.command(robot, linear, angular)
                self.commands += 1
            else:
                self.rejected += 1  # NaN or inf would poison the physics; the robot keeps its command
                if self.rejected == 1:
                    print(f"stage_node: rejected a non-finite cmd_vel for {robot} ({linear}, {angular})", flush=True)
            self._received[robot] += 1
            # published under the lock: the counts go out in order, after the command took effect
            self._pubs[robot]["cmd_vel_received"].publish(self.ros.msgs.UInt32(data=self._received[robot]))

    def _on_clock(self, msg: Any) -> None:
        self.tick(self.ros.seconds(msg.clock))

    def tick(self, t: float) -> None:
        """Step the world to the last grid point at or before ``t`` (when later than now) and publish every
        robot's state stamped ``t``."""
        with self.lock:
            target = last_step_at_or_before(t, self.world.dt)
            if target > self.world.steps:
                self.world.advance(target - self.world.steps)
                self.history.append((self.world.time, self.world.poses()))
            elif t < self.time:
                return  # a clock going backwards (another publisher, a restart): ignored
            self.time = t
            self.ticks += 1
            self._publish(t)

    def run(self, rate: float, until: Optional[float], stop: threading.Event) -> None:
        """Free-running (stageros' own loop): ``interval_sim`` of world time per ``interval_sim / rate`` wall
        seconds, publishing ``/clock`` before each state; until ``until`` (world time) or ``stop``."""
        clock = self.ros.publisher("/clock", self.ros.msgs.Clock)
        self.ros.set_use_sim_time()
        interval = self.world.spec.interval_sim
        wall0, k = _time.monotonic(), 0
        while not stop.is_set() and (until is None or self.time < until - 1e-9):
            k += 1
            t = k * interval
            delay = wall0 + t / rate - _time.monotonic()
            if delay > 0 and stop.wait(delay):
                break
            clock.publish(self.ros.clock(t))
            self.tick(t)

    def _publish(self, t: float) -> None:
        msgs = self.ros.msgs
        stamp = self.ros.stamp(t)
        for robot in self.world.robots:
            pubs = self._pubs[robot.name]
            frame = robot.name
            for topic, pose in (("odom", robot.odometry), ("base_pose_ground_truth", robot.pose)):
                msg = msgs.Odometry()
                msg.header.stamp, msg.header.frame_id = stamp, f"{frame}/odom"
                msg.child_frame_id = f"{frame}/base_footprint"
                msg.pose.pose.position.x, msg.pose.pose.position.y = float(pose.x), float(pose.y)
                msg.pose.pose.orientation = self.ros.quaternion(pose.theta)
                msg.twist.twist.linear.x, msg.twist.twist.angular.z = float(robot.linear), float(robot.angular)
                pubs[topic].publish(msg)
            pubs["stall"].publish(msgs.Bool(data=bool(robot.stall)))
            sensors = robot.spec.sensors
            if not sensors or not robot.ranges:
                continue
            s = sensors[0]
            scan = msgs.LaserScan()
            scan.header.stamp, scan.header.frame_id = stamp, f"{frame}/base_laser_link"
            n = len(robot.ranges)
            scan.angle_min, scan.angle_max = (-s.fov / 2, s.fov / 2) if n > 1 else (0.0, 0.0)
            scan.angle_increment = s.fov / (n - 1) if n > 1 else 0.0
            scan.range_min, scan.range_max = float(s.range_min), float(s.range_max)
            scan.ranges = [float(r) for r in robot.ranges]
            pubs["base_scan"].publish(scan)
            rng = msgs.Range()
            rng.header.stamp, rng.header.frame_id = stamp, f"{frame}/base_laser_link"
            rng.radiation_type, rng.field_of_view = msgs.Range.ULTRASOUND, float(s.fov)
            rng.min_range, rng.max_range, rng.range = float(s.range_min), float(s.range_max), float(min(robot.ranges))
            pubs["range"].publish(rng)

    def summary(self) -> dict[str, Any]:
        """What the node did: every stepping tick's time and poses, the stall counts, the counters."""
        with self.lock:
            return {"times": [t for t, _ in self.history],
                    "poses": [{n: [p.x, p.y, p.theta] for n, p in poses.items()} for _, poses in self.history],
                    "stall_steps": {r.name: r.stall_steps for r in self.world.robots},
                    "commands": self.commands, "rejected": self.rejected, "ticks": self.ticks,
                    "time": self.world.time}


def last_step_at_or_before(t: float, dt: float) -> int:
    """The index of the last step boundary at or before ``t``, within ROS time's resolution: a stamp is
    whole nanoseconds (``rospy.Time.from_sec`` truncates), so ``0.7999999999999999`` arrives as
    ``0.799999999`` and must still be step 80 of ``dt = 0.01``; hence a tolerance of 2 ns plus 1e-9
    relative."""
    n = round(t / dt)
    if abs(n * dt - t) <= 2e-9 + 1e-9 * abs(t):
        return n
    return math.floor(t / dt)


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command (see the module docstring)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.federates.ros_bridge.stage_node",
                                     description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("world", help="a Stage .world file")
    parser.add_argument("--ros", type=int, choices=(1, 2), default=None,
                        help="the ROS of the node (default: found from the environment and what is installed)")
    parser.add_argument("--dt", type=float, default=0.01, help="physics step (s)")
    parser.add_argument("--watchdog", type=float, default=0.2, help="stop a robot without cmd_vel for this "
                                                                    "long (s; 0: never)")
    parser.add_argument("--rate", type=float, default=None,
                        help="run on its own clock at R times real time (default: follow /clock)")
    parser.add_argument("--until", type=float, default=None, help="with --rate: stop at this world time")
    parser.add_argument("--summary", help="write the run's summary (JSON) here at the end")
    parser.add_argument("--snapshot", help="write a PNG of the world, with trails, here at the end")
    parser.add_argument("--node-name", default="stage")
    args = parser.parse_args(argv)
    version = args.ros or detect()
    if version == 2:
        ros2_env.reexec_with_ros2()  # the dynamic loader reads the wheels' library path only at start
    world = World(read_world(args.world), dt=args.dt, watchdog=args.watchdog or None)
    node = StageNode(world, args.node_name, select(version))
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    node.start(follow_clock=args.rate is None)
    print(f"stage_node ready: {len(world.robots)} robots, " + ("following /clock" if args.rate is None
                                                               else f"own clock at {args.rate}x"), flush=True)
    if args.rate is None:
        while not stop.wait(0.5):
            pass
    else:
        node.run(args.rate, args.until, stop)
    node.close()
    summary = node.summary()
    if args.summary:
        with open(args.summary, "w") as f:
            json.dump(summary, f)
    if args.snapshot:
        poses = [p for _, p in node.history]
        write_labelled_snapshot(world, args.snapshot, f"stage node: the world at {world.time:.1f} s, with trails",
                                trails=trajectories(poses) if poses else None)
    print(f"stage_node stopped at {world.time!r} ({node.ticks} ticks, {node.commands} commands)", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
