"""Paper 1's scenario through ROS: the robot world federate, the ROS bridge, and the paper's controllers
as a plain ROS node in another process, as in ros-ptolemy-hla-iess2015 (Stage behind a ROS bridge, the
"Control" script commanding the avatar, a Python ROS node driving the obstacles).

    python -m hlacore.experiments.paper1.ros [OUTDIR] [--rtig HOST:PORT] [--duration 30]
        [--controller node|de] [--ros 1|2]

``--controller de`` plays paper 1's own chain instead (:mod:`.chain`): the controller a DE-engine
federate, the world a stageros-style ROS node, the bridge between them, each in its own process; it writes
``paper1-de-trace.csv``, ``paper1-de-snapshot.png`` and ``paper1-de-trajectories.png``; with ``--ros 2``
the bridge and the world node speak ROS 2 (no master is started). The default
(``node``) is described below.

One process holds the world federate (on a thread) and the bridge (timed, ``/clock``, waiting each cycle
for the controllers' answers: a lockstep through ROS); the node process (``--node``) subscribes
``/avatar/range`` and answers each reading with a go / slow / stop Twist on ``/avatar/cmd_vel``
(:class:`.scenario.Controller`), and drives each obstacle at 0.3 m/s on
``/obstacle<i>/cmd_vel`` until its ground truth (``/obstacle<i>/base_pose_ground_truth``) has travelled 5 m.
On ROS 1, without a ROS master at ``$ROS_MASTER_URI`` it starts ``roscore`` on a free loopback port and stops it
(by pid) at the end; on ROS 2 (``--ros 2``) there is no master, and the command re-executes itself once with
ROS 2's environment (:mod:`~hlacore.federates.ros_bridge.ros2_env`), which the node process inherits. Without
``--rtig`` it uses an in-process gateway. It prints the checks and one JSON summary
line, writes ``paper1-ros-trace.csv`` and a snapshot (and, with matplotlib, the trajectory plot) into
OUTDIR (default ``paper1-ros-out``), and exits 1 if a check fails.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import pathlib
import signal
import subprocess
import sys
import threading
from typing import Any, Callable, Optional, Sequence

import hlacore
import hlacore.rti as rti
from hlacore.federates.robot_world import FEDERATION, FOM_PATH, World, WorldFederate, render
from hlacore.federates.ros_bridge import ros2_env
from hlacore.federates.ros_bridge.bridge import RosBridge, world_mappings
from hlacore.federates.ros_bridge.children import stop_process
from hlacore.federates.ros_bridge.master import ros_master
from hlacore.federates.ros_bridge.runner import WorldThread, wait_wired
from hlacore.federates.ros_bridge.versions import detect, select

from ..cli import run_command

from . import scenario as paper1
from .checks import HALF, WALL_FACE, Result, check, held_back  # noqa: F401  (HALF, WALL_FACE: re-exported, they were here)

#: With ``--record`` (``--controller de``): the run's recording in OUTDIR, the federation's events and the
#: bridged ROS topics in one MCAP file.
RECORDING = "paper1-de.mcap"

# ---- the ROS node (the paper's controllers), in its own process ----

def node_main(ros: Optional[int] = None, timeout: float = 600.0) -> int:
    """The controllers' ROS node, on ROS ``ros`` (1 or 2; None: found): answers each avatar Range and each
    obstacle pose with a Twist, with the QoS the bridge gives those topics (ROS 2)."""
    from hlacore.federates.robot_world import codec
    from hlacore.federates.ros_bridge.ros_api import reliable

    api = select(ros)
    api.init_node("paper1_control")
    msgs = api.msgs
    controller = paper1.Controller()
    drive = paper1.ObstacleDriver()
    pubs = {name: api.publisher(f"/{name}/cmd_vel", msgs.Twist, reliable(codec.INTERACTION))
            for name in ("avatar",) + paper1.OBSTACLES}

    def twist(linear: float) -> Any:
        msg = msgs.Twist()
        msg.linear.x = linear
        return msg

    def on_range(msg: Any) -> None:
        pubs["avatar"].publish(twist(controller(msg.range)))

    def on_pose(name: str) -> Callable[[Any], None]:
        return lambda msg: pubs[name].publish(twist(drive(name, msg.pose.pose.position.y)))

    subs = [api.subscriber("/avatar/range", msgs.Range, on_range, reliable("ranges"))]
    subs += [api.subscriber(f"/{n}/base_pose_ground_truth", msgs.Odometry, on_pose(n), reliable("pose"))
             for n in paper1.OBSTACLES]
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    print("paper1_control ready", flush=True)
    stop.wait(timeout)
    for sub in subs:
        api.unsubscribe(sub)
    api.shutdown("done")
    return 0


# ---- the scenario ----

def run(address: str, duration: float = 30.0, period: float = 0.1, dt: float = 0.01,
        node_timeout: float = 60.0, cycle_timeout: float = 30.0, input_timeout: float = 5.0,
        ros: Optional[int] = None) -> Result:
    """Play the scenario on the gateway at ``address`` on ROS ``ros`` (None: found): ROS 1 with the master of
    ``$ROS_MASTER_URI``, ROS 2 in a process that has its environment (``ros2_env``). This process's ROS node is
    the bridge: call once per process."""
    creator = rti.RTIAmbassador(address)
    creator.createFederationExecution(FEDERATION, str(FOM_PATH))
    world = WorldFederate.join(World(paper1.world_spec(), dt=dt, watchdog=0.2), address, period=period,
                               lookahead=period)
    result = Result()
    node: Optional[subprocess.Popen[str]] = None
    api = select(ros)
    bridge = RosBridge(world_mappings(paper1.world_spec()), address, period=period, clock=True,
                       await_inputs=input_timeout, ros=api)
    try:
        bridge.start()
        node = subprocess.Popen([sys.executable, "-m", "hlacore.experiments.paper1.ros", "--node", "--ros",
                                 str(api.version)],
                                stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                text=True)
        wired = ["/avatar/range", "/avatar/cmd_vel"] + [f"/{n}/{t}" for n in paper1.OBSTACLES
                                                        for t in ("base_pose_ground_truth", "cmd_vel")]
        if not wait_wired(bridge, wired, node, node_timeout):
            raise RuntimeError(f"the control node did not connect: {bridge.connections()}")
        world_thread = WorldThread(world, duration, cycle_timeout, bridge)
        bridge.spin(until=duration, cycle_timeout=0.05)
        world_thread.join()
    finally:
        if node is not None:
            stop_process(node)
            if node.stdout is not None:
                node.stdout.close()
        result.late_cycles, result.sent = bridge.late_cycles, bridge.sent
        if bridge.rtia is not None:
            bridge.close()
        world.resign()
        creator.destroyFederationExecution(FEDERATION)
    result.times = [t for t, _ in world.history]
    result.poses = [p for _, p in world.history]
    result.stall_steps = {r.name: r.stall_steps for r in world.world.robots}
    result.checks = check(result)
    result.world = world.world
    return result


def write_outputs(result: Result, directory: str) -> list[str]:
    """The trace (CSV: grant time and every robot's x, y), a snapshot with trails and, with matplotlib, the
    trajectory plot; returns the files written."""
    import csv

    out = pathlib.Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    world = result.world
    if world is None:
        raise ValueError("the result holds no world")
    names = [r.name for r in world.robots]
    with open(out / "paper1-ros-trace.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["time"] + [f"{n}_{c}" for n in names for c in "xy"])
        for t, poses in zip(result.times, result.poses):
            writer.writerow([repr(t)] + [repr(c) for n in names for c in (poses[n].x, poses[n].y)])
    written = [str(out / "paper1-ros-trace.csv")]
    tracks = render.trajectories(result.poses)
    written.append(str(render.write_labelled_snapshot(world, out / "paper1-ros-snapshot.png",
                                                      "paper 1 through ROS: the world at the end, with trails",
                                                      trails=tracks)))
    try:
        written.append(str(render.plot_trajectories(world, result.poses, out / "paper1-ros-trajectories.png",
                                                    title="paper 1 through ROS",
                                                    marks={"avatar held back": held_back(result.poses)})))
    except ImportError as exc:
        print(f"no trajectory plot: {exc}")
    return written


def main(argv: Optional[Sequence[str]] = None) -> int:
    """The command (see the module docstring)."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.experiments.paper1.ros")
    parser.add_argument("outdir", nargs="?", default="paper1-ros-out")
    parser.add_argument("--rtig", default=None, help="gateway HOST:PORT (default: an in-process gateway)")
    parser.add_argument("--duration", type=float, default=30.0)
    parser.add_argument("--controller", choices=("node", "de"), default="node",
                        help="node: world federate + bridge + the controllers as a rospy node; de: the DE "
                             "controller federate + bridge + the world as a stageros-style ROS node")
    parser.add_argument("--ros", type=int, choices=(1, 2), default=None,
                        help="the ROS between the bridge and the ROS node (default: found from the environment "
                             "and what is installed)")
    parser.add_argument("--record", action="store_true",
                        help="with --controller de and the in-process gateway: record the run into "
                             "OUTDIR/paper1-de.mcap, the federation's events and the bridged ROS topics in one file")
    parser.add_argument("--node", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.node:
        return node_main(args.ros)
    if args.controller == "de":
        if args.record and args.rtig:
            parser.error("--record needs the in-process gateway (with rtig: rtig --record, the bridge's "
                         "--record-ros, then ros_bridge.recorder.merge)")
        return _main_de(args.outdir, args.rtig, args.duration, args.ros, args.record)
    ros = args.ros or detect()
    if ros == 2:
        ros2_env.reexec_with_ros2()  # the bridge runs here: rclpy needs its libraries from the start
    with contextlib.ExitStack() as stack:
        if ros == 1:
            stack.enter_context(ros_master())
        address = args.rtig or str(stack.enter_context(hlacore.Gateway(port=0)).address)
        result = run(address, duration=args.duration, ros=ros)
    for name, passed in result.checks.items():
        print(f"{'ok  ' if passed else 'FAIL'} {name}")
    for path in write_outputs(result, args.outdir):
        print(f"wrote {path}")
    print(json.dumps({**result.summary(), "ros": ros}), flush=True)
    return 0 if result.ok else 1


def _main_de(outdir: str, rtig: Optional[str], duration: float, ros: Optional[int] = None,
             record: bool = False) -> int:
    from hlacore.federates.ros_bridge.recorder import merge

    from . import chain as paper1_chain

    ros = ros or detect()
    recording, topics = pathlib.Path(outdir) / RECORDING, pathlib.Path(outdir) / "bridge-topics.mcap"
    if record:
        recording.parent.mkdir(parents=True, exist_ok=True)
    with contextlib.ExitStack() as stack:
        if ros == 1:
            stack.enter_context(ros_master())  # ROS 2 has none: its nodes find each other over DDS
        gateway = hlacore.Gateway(port=0, record=str(recording)) if record else hlacore.Gateway(port=0)
        address = rtig or str(stack.enter_context(gateway).address)
        result = paper1_chain.run(address, outdir, duration=duration, ros=ros,
                                  record_ros=str(topics) if record else None)
    if record:  # the gateway has stopped: its recording is complete
        merge(recording, topics)
        topics.unlink()
        print(f"wrote {recording}")
    for name, passed in result.checks.items():
        print(f"{'ok  ' if passed else 'FAIL'} {name}")
    for path in paper1_chain.write_outputs(result, outdir):
        print(f"wrote {path}")
    print(json.dumps(result.summary()), flush=True)
    return 0 if result.ok else 1


if __name__ == "__main__":
    raise SystemExit(run_command("python -m hlacore.experiments.paper1.ros", main))
