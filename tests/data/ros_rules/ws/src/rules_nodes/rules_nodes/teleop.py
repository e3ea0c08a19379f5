import rclpy
from rclpy.node import Node

from geometry_msgs.msg import Twist


class Teleop(Node):
    """Sends velocity commands on an absolute topic name."""

    def __init__(self):
        super().__init__('teleop')
        self.cmd_pub = self.create_publisher(Twist, '/robo/cmd_vel', 10)


def main():
    rclpy.init()
    rclpy.spin(Teleop())
