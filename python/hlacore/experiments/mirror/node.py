"""The third robot's controller: a plain rospy node (no HLA) running the same "go forward, avoid what the
sonar sees" rule from the robot's ROS odometry and range, publishing Twist.

    python -m hlacore.experiments.mirror.node [--robot rosbot] [--corrected] [--cycle 0.5] [--lookahead 0.1]

It pairs ``/<robot>/odom`` and ``/<robot>/range`` by header stamp (the bridge stamps both with the
federation time ``G + lookahead`` of the state of ``G``). For a state taken at a multiple of the control
cycle it decides anew; for the others it repeats its last command, so that the bridge (waiting for an
answer after each state, ``await_inputs``) and the world's watchdog always hear from it. SIGTERM ends it;
it then prints one JSON line: decisions, avoidances, the modes it went through.
"""

from __future__ import annotations

import argparse
import json
import math
import signal
import threading
from typing import Any, Optional, Sequence

from hlacore.federates.robot_driver.avoid import AvoidParams, make_controller


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the node until SIGTERM/SIGINT or ``--timeout`` wall seconds."""
    parser = argparse.ArgumentParser(prog="python -m hlacore.experiments.mirror.node")
    parser.add_argument("--robot", default="rosbot")
    parser.add_argument("--corrected", action="store_true")
    parser.add_argument("--cycle", type=float, default=0.5)
    parser.add_argument("--lookahead", type=float, default=0.1)
    parser.add_argument("--timeout", type=float, default=900.0)
    args = parser.parse_args(argv)

    from hlacore.federates.ros_bridge import import_rospy

    rospy = import_rospy()
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from sensor_msgs.msg import Range

    controller = make_controller(args.corrected, AvoidParams(cycle=args.cycle))
    lock = threading.Lock()
    odoms: dict[int, tuple[float, float, float]] = {}
    ranges: dict[int, float] = {}
    command = [0.0, 0.0]
    summary: dict[str, Any] = {"decisions": 0, "answers": 0, "modes": []}
    rospy.init_node(f"{args.robot}_control", disable_signals=True)
    pub = rospy.Publisher(f"/{args.robot}/cmd_vel", Twist, queue_size=100)

    def key(stamp: Any) -> int:
        return round(stamp.to_sec() * 1000)  # milliseconds: stamps are multiples of the world's period

    def answer(k: int) -> None:
        """Both halves of the state stamped ``k`` ms are here (called with the lock held)."""
        pose, front = odoms.pop(k), ranges.pop(k)
        taken = k / 1000 - args.lookahead
        cycles = taken / args.cycle
        if taken > 0 and abs(cycles - round(cycles)) < 1e-6:
            command[:] = controller.decide(pose, front)
            summary["decisions"] += 1
            if not summary["modes"] or summary["modes"][-1] != controller.mode:
                summary["modes"].append(controller.mode)
        msg = Twist()
        msg.linear.x, msg.angular.z = command
        pub.publish(msg)
        summary["answers"] += 1

    def on_odom(msg: Odometry) -> None:
        q = msg.pose.pose.orientation
        with lock:
            k = key(msg.header.stamp)
            odoms[k] = (msg.pose.pose.position.x, msg.pose.pose.position.y, 2 * math.atan2(q.z, q.w))
            if k in ranges:
                answer(k)

    def on_range(msg: Range) -> None:
        with lock:
            k = key(msg.header.stamp)
            ranges[k] = float(msg.range)
            if k in odoms:
                answer(k)

    subs = [rospy.Subscriber(f"/{args.robot}/odom", Odometry, on_odom, queue_size=100),
            rospy.Subscriber(f"/{args.robot}/range", Range, on_range, queue_size=100)]
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    print(f"{args.robot}_control ready", flush=True)
    stop.wait(args.timeout)
    for sub in subs:
        sub.unregister()
    with lock:
        summary["avoidances"] = controller.avoidances
        print(json.dumps(summary), flush=True)
    rospy.signal_shutdown("done")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
