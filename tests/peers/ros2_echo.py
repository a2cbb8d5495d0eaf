"""Two plain rclpy roles (no hlacore), for the namespace tests: ``ros2_echo.py talk TOPIC`` publishes a
geometry_msgs/Twist (linear.x = 0, 1, 2, ...) on TOPIC every 10 ms until SIGTERM; ``ros2_echo.py listen TOPIC
N`` prints ``listen ready``, then ``listen got N`` once it has received N of them, waits for SIGTERM and prints
``listen heard K``, the number it received.
Needs the ROS 2 environment (hlacore.federates.ros_bridge.ros2_env)."""

from __future__ import annotations

import signal
import sys
import threading

import rclpy
from geometry_msgs.msg import Twist
from rclpy.signals import SignalHandlerOptions


def main() -> int:
    role, topic = sys.argv[1], sys.argv[2]
    stop = threading.Event()
    signal.signal(signal.SIGTERM, lambda *_: stop.set())
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = rclpy.create_node(f"echo_{role}")
    if role == "talk":
        pub = node.create_publisher(Twist, topic, 10)
        i = 0
        while not stop.wait(0.01):
            msg = Twist()
            msg.linear.x = float(i)
            pub.publish(msg)
            i += 1
    else:
        wanted, got = int(sys.argv[3]), [0]

        def on_twist(msg: Twist) -> None:
            got[0] += 1
            if got[0] == wanted:
                print(f"listen got {wanted}", flush=True)

        node.create_subscription(Twist, topic, on_twist, 10)
        print("listen ready", flush=True)
        while not stop.is_set():
            rclpy.spin_once(node, timeout_sec=0.05)
        print(f"listen heard {got[0]}", flush=True)
    node.destroy_node()
    rclpy.shutdown()
    return 0


if __name__ == "__main__":
    sys.exit(main())
