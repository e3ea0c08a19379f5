import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node

from geometry_msgs.msg import TwistStamped
from planning_interfaces.action import Navigate
from std_msgs.msg import String


class Commander(Node):
    """Sends navigation goals and overrides velocity."""

    def __init__(self):
        super().__init__('commander')
        self.client = ActionClient(self, Navigate, 'navigate')
        self.override_pub = self.create_publisher(TwistStamped, '/robot/cmd_vel', 10)
        self.create_subscription(String, 'mission_status', self.on_status, 10)
        self.report_pub = self.create_publisher(String, f'report_{id(self)}', 10)

    def on_status(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Commander())
