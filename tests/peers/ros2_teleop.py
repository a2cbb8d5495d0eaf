"""A plain rclpy node (no HLA, no hlacore): publishes Twist on PREFIX/cmd_vel at 20 Hz (wall) until it has seen
the robot move on PREFIX/odom (x above THRESHOLD), a LaserScan on PREFIX/base_scan and a Range on PREFIX/range
stamped after that odometry, and /clock when asked; then prints one JSON line of what it saw (with the node's
own ROS time when the odometry came: federation time when started with ``--ros-args -p use_sim_time:=true``)
and exits 0. Exits 2 after TIMEOUT wall seconds. Usage: ros2_teleop.py PREFIX LINEAR THRESHOLD TIMEOUT [--clock]
[--ros-args ...]. Needs the ROS 2 environment (hlacore.federates.ros_bridge.ros2_env)."""

from __future__ import annotations

import json
import sys
import threading
import time
from typing import Any

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from rclpy.utilities import remove_ros_args
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan, Range


def seconds(stamp: Any) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


def main() -> int:
    args = remove_ros_args(sys.argv)
    prefix, linear, threshold, timeout = args[1], float(args[2]), float(args[3]), float(args[4])
    want_clock = "--clock" in args[5:]
    rclpy.init(args=sys.argv, signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node("teleop")
    lock = threading.Lock()
    seen: dict[str, Any] = {"clock": 0.0}

    def on_odom(msg: Odometry) -> None:
        with lock:
            if "odom" not in seen and msg.pose.pose.position.x > threshold:
                seen["odom"] = {"stamp": seconds(msg.header.stamp), "x": msg.pose.pose.position.x,
                                "y": msg.pose.pose.position.y, "qz": msg.pose.pose.orientation.z,
                                "qw": msg.pose.pose.orientation.w, "v": msg.twist.twist.linear.x,
                                "frame": msg.header.frame_id, "child": msg.child_frame_id,
                                "node_time": node.get_clock().now().nanoseconds * 1e-9}

    def on_scan(msg: LaserScan) -> None:
        with lock:
            if "odom" in seen and "scan" not in seen:
                seen["scan"] = {"stamp": seconds(msg.header.stamp), "ranges": [float(r) for r in msg.ranges],
                                "angle_min": msg.angle_min, "angle_max": msg.angle_max,
                                "angle_increment": msg.angle_increment, "range_max": msg.range_max}

    def on_range(msg: Range) -> None:
        with lock:
            if "odom" in seen and "range" not in seen:
                seen["range"] = {"stamp": seconds(msg.header.stamp), "range": msg.range,
                                 "radiation_type": msg.radiation_type}

    def on_clock(msg: Clock) -> None:
        with lock:
            seen["clock"] = max(seen["clock"], seconds(msg.clock))

    qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
    node.create_subscription(Odometry, f"{prefix}/odom", on_odom, qos)
    node.create_subscription(LaserScan, f"{prefix}/base_scan", on_scan, qos)
    node.create_subscription(Range, f"{prefix}/range", on_range, qos)
    if want_clock:
        node.create_subscription(Clock, "/clock", on_clock, qos)
    pub = node.create_publisher(Twist, f"{prefix}/cmd_vel", qos)
    twist = Twist()
    twist.linear.x = linear
    deadline = time.monotonic() + timeout
    next_publish = 0.0
    status = 2
    while time.monotonic() < deadline:
        if time.monotonic() >= next_publish:
            pub.publish(twist)
            next_publish = time.monotonic() + 0.05
        rclpy.spin_once(node, timeout_sec=0.01)
        with lock:
            if {"odom", "scan", "range"} <= set(seen) and (seen["clock"] > 0 or not want_clock):
                status = 0
                break
    with lock:
        seen["use_sim_time"] = node.get_parameter("use_sim_time").value
        print(json.dumps(seen if status == 0 else {"timeout": True, **seen}), flush=True)
    node.destroy_node()
    rclpy.shutdown()
    return status


if __name__ == "__main__":
    sys.exit(main())
