import rclpy
from rclpy.node import Node

from geometry_msgs.msg import Twist


class Arbiter(Node):
    """Chooses between teleoperation and autonomy."""

    def __init__(self):
        super().__init__('arbiter')
        self.create_publisher(Twist, 'cmd_vel', 10)
        self.create_subscription(Twist, 'cmd_vel_teleop', self.on_teleop, 10)

    def on_teleop(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Arbiter())
