"""A plain rospy node (no HLA) standing for a simulator whose first messages are lost: for each /clock tick
it publishes PREFIX/odom and PREFIX/base_pose_ground_truth stamped with it, except for the first IGNORED
ticks, which it only counts (as when rospy's publisher has not yet added the bridge's subscriber); it also
advertises PREFIX/stall and subscribes PREFIX/cmd_vel, so that a bridge sees every topic connected. Prints
"deaf_start ready" once subscribed, runs until SIGTERM, then prints one JSON line: the ticks it ignored and
the stamps it published. Usage: ros_deaf_start.py PREFIX IGNORED"""

from __future__ import annotations

import json
import signal
import sys
import threading

from hlacore.federates.ros_bridge import import_rospy

rospy = import_rospy()
from geometry_msgs.msg import Twist  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rosgraph_msgs.msg import Clock  # noqa: E402
from std_msgs.msg import Bool  # noqa: E402


def main() -> int:
    prefix, ignored = sys.argv[1], int(sys.argv[2])
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    rospy.init_node("deaf_start", disable_signals=True)
    pubs = [rospy.Publisher(f"{prefix}/{topic}", Odometry, queue_size=100)
            for topic in ("odom", "base_pose_ground_truth")]
    stall = rospy.Publisher(f"{prefix}/stall", Bool, queue_size=10)
    rospy.Subscriber(f"{prefix}/cmd_vel", Twist, lambda msg: None, queue_size=10)
    seen: dict = {"ignored": 0, "published": []}
    lock = threading.Lock()

    def on_clock(msg: Clock) -> None:
        with lock:
            if seen["ignored"] < ignored:
                seen["ignored"] += 1
                return
            odom = Odometry()
            odom.header.stamp = msg.clock
            odom.pose.pose.orientation.w = 1.0
            for pub in pubs:
                pub.publish(odom)
            seen["published"].append(msg.clock.to_sec())

    rospy.Subscriber("/clock", Clock, on_clock, queue_size=100)
    print("deaf_start ready", flush=True)
    stop.wait()
    with lock:
        print(json.dumps(seen), flush=True)
    stall.unregister()
    rospy.signal_shutdown("done")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
