"""Plain rclpy nodes (no hlacore) that give a bridge bad input, for tests/federates/test_ros2_bridge.py; each
publishes every 50 ms until SIGTERM (or SIGKILL: the node that dies), after printing ``ROLE ready``, and prints
``ROLE matched`` once a subscription takes its messages:

    ros2_bad.py nan TOPIC      geometry_msgs/Twist with linear.x = NaN
    ros2_bad.py wrong TOPIC    std_msgs/String on TOPIC (a topic the bridge reads as another type)
    ros2_bad.py odom TOPIC     a well-formed nav_msgs/Odometry (a robot node, until it is killed)
    ros2_bad.py besteffort TOPIC   the same, best effort (ROS 2's sensor-data QoS), which a reliable
                               subscription does not take

Needs the ROS 2 environment (hlacore.federates.ros_bridge.ros2_env)."""

from __future__ import annotations

import math
import signal
import sys
import threading

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.qos import QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from std_msgs.msg import String


def main() -> int:
    role, topic = sys.argv[1], sys.argv[2]
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node(f"bad_{role}")
    kinds = {"nan": Twist, "wrong": String, "odom": Odometry, "besteffort": Odometry}
    reliability = ReliabilityPolicy.BEST_EFFORT if role == "besteffort" else ReliabilityPolicy.RELIABLE
    pub = node.create_publisher(kinds[role], topic, QoSProfile(depth=10, reliability=reliability))
    print(f"{role} ready", flush=True)
    x, matched = 0.0, False
    while not stop.wait(0.05):
        if not matched and pub.get_subscription_count() > 0:
            matched = True
            print(f"{role} matched", flush=True)
        if role == "nan":
            msg = Twist()
            msg.linear.x = math.nan
        elif role == "wrong":
            msg = String(data="not a pose")
        else:
            x += 0.01
            msg = Odometry()
            msg.header.stamp = node.get_clock().now().to_msg()
            msg.pose.pose.position.x, msg.pose.pose.orientation.w = x, 1.0
        pub.publish(msg)
    node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
