import rclpy
from rclpy.node import Node

from nav_msgs.msg import Odometry


class WheelOdometry(Node):
    """Publishes the wheel odometry the planner listens to, and a raw copy nobody hears."""

    def __init__(self):
        super().__init__('odometry')
        self.pub = self.create_publisher(Odometry, 'odom', 10)
        self.debug_pub = self.create_publisher(Odometry, 'odom_raw', 10)


def main():
    rclpy.init()
    rclpy.spin(WheelOdometry())
