import rclpy
from rclpy.node import Node

from nav_msgs.msg import Odometry


class Recorder(Node):
    """Records odometry to disk."""

    def __init__(self):
        super().__init__('recorder')
        self.create_subscription(Odometry, 'odom', self.on_odom, 10)

    def on_odom(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Recorder())
