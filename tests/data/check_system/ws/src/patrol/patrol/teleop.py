import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy

from geometry_msgs.msg import Twist


class Teleop(Node):
    """Sends velocity commands from a keyboard, best effort."""

    def __init__(self):
        super().__init__('teleop')
        self.cmd_pub = self.create_publisher(
            Twist, 'cmd_vel', QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))


def main():
    rclpy.init()
    rclpy.spin(Teleop())
