"""A stand-in for your robot on ROS 2, as ROS 2 sees it: an rclpy node that takes geometry_msgs/Twist on
/NAME/cmd_vel and publishes nav_msgs/Odometry on /NAME/odom and sensor_msgs/Range on /NAME/range at 20 Hz. It
drives along x (unicycle model, odometry integrated from the commanded speeds) towards a wall at WALL metres and
measures the distance to it. The ROS 1 stand-in, my_robot.py, does the same with rospy. Replace it by your
robot's driver; docs/own-robot.md says what the bridge expects of it.

    python -m hlacore.federates.ros_bridge.ros2_env python docs/own-robot/my_robot2.py NAME [--wall 2.0]

(``ros2_env`` runs it with the environment of hlacore's ROS 2 wheels; in a sourced ROS 2 install:
``python3 my_robot2.py NAME``.) Prints "my_robot ready" once its topics are advertised; Ctrl-C (or SIGTERM)
stops it."""

from __future__ import annotations

import argparse
import math
import signal
import threading

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.signals import SignalHandlerOptions
from sensor_msgs.msg import Range

RATE_HZ = 20.0
MAX_RANGE = 4.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("name")
    parser.add_argument("--wall", type=float, default=2.0, help="the wall's x (m)")
    args = parser.parse_args()
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node(f"{args.name}_driver")
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    signal.signal(signal.SIGINT, lambda *_: stop.set())

    command = {"linear": 0.0, "angular": 0.0}

    def on_twist(msg: Twist) -> None:  # called from rclpy.spin_once, on this thread
        command.update(linear=msg.linear.x, angular=msg.angular.z)

    node.create_subscription(Twist, f"/{args.name}/cmd_vel", on_twist, 10)
    odom_topic = node.create_publisher(Odometry, f"/{args.name}/odom", 10)
    range_topic = node.create_publisher(Range, f"/{args.name}/range", 10)
    print("my_robot ready", flush=True)

    x = y = theta = 0.0
    period = 1.0 / RATE_HZ
    next_step = node.get_clock().now().nanoseconds * 1e-9
    while not stop.is_set():
        rclpy.spin_once(node, timeout_sec=max(0.0, next_step - node.get_clock().now().nanoseconds * 1e-9))
        now = node.get_clock().now()
        if now.nanoseconds * 1e-9 < next_step:
            continue
        next_step += period
        linear, angular = command["linear"], command["angular"]
        x += linear * math.cos(theta) * period
        y += linear * math.sin(theta) * period
        theta += angular * period
        stamp = now.to_msg()

        odom = Odometry()
        odom.header.stamp, odom.header.frame_id, odom.child_frame_id = stamp, f"{args.name}/odom", "base_footprint"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = math.sin(theta / 2), math.cos(theta / 2)
        odom.twist.twist.linear.x, odom.twist.twist.angular.z = linear, angular
        odom_topic.publish(odom)

        sonar = Range()
        sonar.header.stamp, sonar.header.frame_id = stamp, f"{args.name}/sonar"
        sonar.radiation_type, sonar.field_of_view = Range.ULTRASOUND, 0.3
        sonar.min_range, sonar.max_range = 0.02, MAX_RANGE
        sonar.range = min(max(args.wall - x, sonar.min_range), MAX_RANGE)
        range_topic.publish(sonar)
    print(f"my_robot stopped at x={x:.3f} m", flush=True)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == "__main__":
    main()
