"""A stand-in for your robot, as ROS sees it: a rospy node that takes geometry_msgs/Twist on /NAME/cmd_vel
and publishes nav_msgs/Odometry on /NAME/odom and sensor_msgs/Range on /NAME/range at 20 Hz. It drives
along x (unicycle model, odometry integrated from the commanded speeds) towards a wall at WALL metres and
measures the distance to it. Replace it by your robot's driver; docs/own-robot.md says what the bridge
expects of it.

    python docs/own-robot/my_robot.py NAME [--wall 2.0]

Prints "my_robot ready" once its topics are advertised; Ctrl-C (or SIGTERM) stops it."""

from __future__ import annotations

import argparse
import math
import signal
import threading

from hlacore.federates.ros_bridge import import_rospy

rospy = import_rospy()  # Debian's rospy from the project's Python; with ROS's own Python: import rospy
from geometry_msgs.msg import Twist  # noqa: E402
from nav_msgs.msg import Odometry  # noqa: E402
from sensor_msgs.msg import Range  # noqa: E402

RATE_HZ = 20.0
MAX_RANGE = 4.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("name")
    parser.add_argument("--wall", type=float, default=2.0, help="the wall's x (m)")
    args = parser.parse_args()
    rospy.init_node(f"{args.name}_driver", disable_signals=True)
    signal.signal(signal.SIGTERM, lambda *_: rospy.signal_shutdown("SIGTERM"))
    signal.signal(signal.SIGINT, lambda *_: rospy.signal_shutdown("SIGINT"))

    lock = threading.Lock()
    command = {"linear": 0.0, "angular": 0.0}

    def on_twist(msg: Twist) -> None:
        with lock:
            command.update(linear=msg.linear.x, angular=msg.angular.z)

    rospy.Subscriber(f"/{args.name}/cmd_vel", Twist, on_twist, queue_size=10)
    odom_topic = rospy.Publisher(f"/{args.name}/odom", Odometry, queue_size=10)
    range_topic = rospy.Publisher(f"/{args.name}/range", Range, queue_size=10)
    print("my_robot ready", flush=True)

    x = y = theta = 0.0
    period = 1.0 / RATE_HZ
    rate = rospy.Rate(RATE_HZ)
    while not rospy.is_shutdown():
        with lock:
            linear, angular = command["linear"], command["angular"]
        x += linear * math.cos(theta) * period
        y += linear * math.sin(theta) * period
        theta += angular * period
        now = rospy.Time.now()

        odom = Odometry()
        odom.header.stamp, odom.header.frame_id, odom.child_frame_id = now, f"{args.name}/odom", "base_footprint"
        odom.pose.pose.position.x, odom.pose.pose.position.y = x, y
        odom.pose.pose.orientation.z, odom.pose.pose.orientation.w = math.sin(theta / 2), math.cos(theta / 2)
        odom.twist.twist.linear.x, odom.twist.twist.angular.z = linear, angular
        odom_topic.publish(odom)

        sonar = Range()
        sonar.header.stamp, sonar.header.frame_id = now, f"{args.name}/sonar"
        sonar.radiation_type, sonar.field_of_view = Range.ULTRASOUND, 0.3
        sonar.min_range, sonar.max_range = 0.02, MAX_RANGE
        sonar.range = min(max(args.wall - x, sonar.min_range), MAX_RANGE)
        range_topic.publish(sonar)
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break
    print(f"my_robot stopped at x={x:.3f} m", flush=True)


if __name__ == "__main__":
    main()
