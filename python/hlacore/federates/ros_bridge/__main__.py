"""``python -m hlacore.federates.ros_bridge``: run the ROS bridge for robots of the robot world.

    python -m hlacore.federates.ros_bridge --rtig HOST:PORT --robot avatar [--robot ...] [--world FILE]
        [--untimed] [--period 0.1] [--lookahead 0.1] [--clock] [--rate R] [--until T]
    python -m hlacore.federates.ros_bridge --rtig HOST:PORT --world-node FILE [--robot ...] --clock
        [--await-state 5] [--wait-connections 30] ...
    python -m hlacore.federates.ros_bridge --rtig HOST:PORT --robot-node NAME [--sensor scan|range|none]
        --untimed
    ... [--ros 1|2] [--record-ros FILE.mcap]

``--world`` bridges robots simulated by an HLA federate (the robot world) to ROS; ``--world-node`` bridges
robots simulated by a ROS node (``python -m hlacore.federates.ros_bridge.stage_node FILE``) to HLA: the
``cmd_vel`` interactions go out as Twist, the node's odometry, ground truth, scan and stall come back as
``WorldRobot`` attributes of instances the bridge registers. ``--robot-node NAME`` does the same for one
robot with no world file, a real one for instance (docs/own-robot.md): its topics under ``/NAME``.

``--ros 1`` bridges ROS 1 (rospy; the master is ``$ROS_MASTER_URI``, set ``ROS_IP=127.0.0.1`` on loopback),
``--ros 2`` ROS 2 (rclpy over DDS, ``$ROS_DOMAIN_ID``; the command gives itself the environment the ROS 2
wheels need, re-executing once); without ``--ros``, the ROS found by ``ros_api.detect`` (``$ROS_VERSION``,
else ROS 1 when ``$ROS_MASTER_URI`` is set, else ROS 2 when installed). Prints ``ros_bridge ready``
once the node is up and the federate joined (and time-enabled), ``ros_bridge stopped at T`` at the end;
SIGTERM or SIGINT stops it.
"""

from __future__ import annotations

import argparse
import signal
import sys
from typing import Any, Optional, Sequence

from hlacore.federates.robot_world import read_world

from . import ros2_env
from .bridge import Mapping, RosBridge, node_mappings, stage_mappings, world_mappings, world_node_mappings
from .versions import detect, select


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Parse the arguments, start the bridge, spin until stopped; returns the exit status."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.federates.ros_bridge", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rtig", default=None, help="gateway HOST:PORT (default $HLACORE_RTIG)")
    parser.add_argument("--ros", type=int, choices=(1, 2), default=None,
                        help="the ROS to bridge (default: found from the environment and what is installed)")
    parser.add_argument("--federation", default="RobotWorld")
    parser.add_argument("--robot", action="append", default=[], help="a robot to bridge (repeatable)")
    parser.add_argument("--world", help="a .world file: bridge its robots (or the --robot ones) with their "
                                        "ranger's field of view and range")
    parser.add_argument("--world-node", help="a .world file simulated by a stageros-style ROS node: bridge its "
                                             "robots (or the --robot ones) the other way")
    parser.add_argument("--robot-node", action="append", default=[], metavar="NAME",
                        help="a robot that is a ROS node, its topics under /NAME: bridge it the other way "
                             "(repeatable)")
    parser.add_argument("--sensor", choices=("scan", "range", "none"), default="scan",
                        help="with --robot-node: the ranger topic, /NAME/base_scan or /NAME/range (default scan)")
    parser.add_argument("--await-state", type=float, default=None, metavar="SECONDS",
                        help="after each /clock, wait for the node's state stamped with it (lockstep)")
    parser.add_argument("--acks", action="store_true",
                        help="with --world-node: before each /clock, wait until the node has counted every Twist "
                             "on /<robot>/cmd_vel_received (hlacore's stage node; stageros has no such topic)")
    parser.add_argument("--wait-connections", type=float, default=None, metavar="SECONDS",
                        help="before advancing, wait until every bridged topic is connected")
    parser.add_argument("--untimed", action="store_true", help="neither regulating nor constrained")
    parser.add_argument("--period", type=float, default=0.1)
    parser.add_argument("--lookahead", type=float, default=None, help="default: the period")
    parser.add_argument("--clock", action="store_true", help="publish /clock and set /use_sim_time")
    parser.add_argument("--rate", type=float, default=None,
                        help="federation seconds per wall second (default: as fast as granted)")
    parser.add_argument("--until", type=float, default=None, help="stop at this federation time")
    parser.add_argument("--node-name", default="hla_bridge")
    parser.add_argument("--record-ros", metavar="FILE.mcap",
                        help="write every bridged ROS message here (MCAP, with its schema; merge it into the "
                             "gateway's recording with hlacore.federates.ros_bridge.recorder.merge)")
    args = parser.parse_args(argv)
    mappings: list[Mapping] = []
    if args.world or args.world_node:
        if args.world:
            mappings += world_mappings(read_world(args.world), args.robot or None)
        if args.world_node:
            mappings += world_node_mappings(read_world(args.world_node), args.robot or None, acks=args.acks)
    else:
        mappings += [m for robot in args.robot for m in stage_mappings(robot)]
    sensor = None if args.sensor == "none" else args.sensor
    mappings += [m for robot in args.robot_node for m in node_mappings(robot, sensor=sensor, acks=args.acks)]
    if not mappings:
        parser.error("nothing to bridge: give --robot, --robot-node, --world or --world-node")
    version = args.ros or detect()
    if version == 2:
        ros2_env.reexec_with_ros2()  # the dynamic loader reads the wheels' library path only at start
    bridge = RosBridge(mappings, args.rtig, federation=args.federation, node_name=args.node_name,
                       timed=not args.untimed, period=args.period, lookahead=args.lookahead, clock=args.clock,
                       rate=args.rate, await_state=args.await_state, ros=select(version), record=args.record_ros)

    def on_signal(signum: int, frame: Any) -> None:
        bridge.stop()

    signal.signal(signal.SIGTERM, on_signal)
    signal.signal(signal.SIGINT, on_signal)
    bridge.start()
    try:
        if args.wait_connections is not None:
            bridge.wait_connected(args.wait_connections)
        print("ros_bridge ready", flush=True)
        end = bridge.spin(args.until)
    finally:
        bridge.close()
    print(f"ros_bridge stopped at {end!r} (sent {bridge.sent} cmd_vel, published {bridge.published}; "
          f"{bridge.updates} updates, {bridge.commands_out} Twists out, {bridge.late_states} late states, "
          f"{bridge.late_acks} late acks, "
          f"{bridge.ignored} ignored, {bridge.rejected} rejected; ROS {bridge.ros.version})", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
