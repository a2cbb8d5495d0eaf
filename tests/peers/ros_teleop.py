"""A plain rospy node (no HLA): publishes Twist on PREFIX/cmd_vel at 20 Hz (wall) until it has seen the
robot move on PREFIX/odom (x above THRESHOLD), a LaserScan on PREFIX/base_scan and a Range on PREFIX/range
stamped after that odometry, and /clock when asked; then prints one JSON line of what it saw and exits 0.
Exits 2 after TIMEOUT wall seconds. Usage: ros_teleop.py PREFIX LINEAR THRESHOLD TIMEOUT [--clock]"""

from __future__ import annotations

import json
import sys
import threading
import time

from hlacore.federates.ros_bridge import import_rospy

rospy = import_rospy()
from geometry_msgs.msg import Twist  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from rosgraph_msgs.msg import Clock  # noqa: E402
from sensor_msgs.msg import LaserScan, Range  # noqa: E402


def main() -> int:
    prefix, linear, threshold, timeout = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    want_clock = "--clock" in sys.argv[5:]
    lock = threading.Lock()
    seen: dict = {"clock": 0.0}
    rospy.init_node("teleop", disable_signals=True)

    def on_odom(msg: Odometry) -> None:
        with lock:
            if "odom" not in seen and msg.pose.pose.position.x > threshold:
                seen["odom"] = {"stamp": msg.header.stamp.to_sec(), "x": msg.pose.pose.position.x,
                                "y": msg.pose.pose.position.y, "qz": msg.pose.pose.orientation.z,
                                "qw": msg.pose.pose.orientation.w, "v": msg.twist.twist.linear.x,
                                "frame": msg.header.frame_id, "child": msg.child_frame_id}

    def on_scan(msg: LaserScan) -> None:
        with lock:
            if "odom" in seen and "scan" not in seen:
                seen["scan"] = {"stamp": msg.header.stamp.to_sec(), "ranges": list(msg.ranges),
                                "angle_min": msg.angle_min, "angle_max": msg.angle_max,
                                "angle_increment": msg.angle_increment, "range_max": msg.range_max}

    def on_range(msg: Range) -> None:
        with lock:
            if "odom" in seen and "range" not in seen:
                seen["range"] = {"stamp": msg.header.stamp.to_sec(), "range": msg.range,
                                 "radiation_type": msg.radiation_type}

    def on_clock(msg: Clock) -> None:
        with lock:
            seen["clock"] = max(seen["clock"], msg.clock.to_sec())

    subs = [rospy.Subscriber(f"{prefix}/odom", Odometry, on_odom),
            rospy.Subscriber(f"{prefix}/base_scan", LaserScan, on_scan),
            rospy.Subscriber(f"{prefix}/range", Range, on_range)]
    if want_clock:
        subs.append(rospy.Subscriber("/clock", Clock, on_clock))
    pub = rospy.Publisher(f"{prefix}/cmd_vel", Twist, queue_size=10)
    twist = Twist()
    twist.linear.x = linear
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        pub.publish(twist)
        with lock:
            done = {"odom", "scan", "range"} <= set(seen) and (seen["clock"] > 0 or not want_clock)
        if done:
            break
        time.sleep(0.05)
    else:
        print(json.dumps({"timeout": True, **seen}), flush=True)
        rospy.signal_shutdown("timeout")
        return 2
    with lock:
        seen["use_sim_time"] = rospy.get_param("/use_sim_time", False)
        print(json.dumps(seen), flush=True)
    for sub in subs:
        sub.unregister()
    rospy.signal_shutdown("done")
    return 0


if __name__ == "__main__":
    sys.exit(main())
