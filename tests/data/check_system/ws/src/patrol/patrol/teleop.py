import rclpy
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy

from geometry_msgs.msg import PoseWithCovarianceStamped, Twist


class Teleop(Node):
    """Sends velocity commands from a keyboard, best effort, and the robot's pose to start from."""

    def __init__(self):
        super().__init__('teleop')
        self.cmd_pub = self.create_publisher(
            Twist, 'cmd_vel', QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT))
        self.pose_pub = self.create_publisher(PoseWithCovarianceStamped, 'initialpose', 10)


def main():
    rclpy.init()
    rclpy.spin(Teleop())
