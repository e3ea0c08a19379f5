import rclpy
from rclpy.node import Node

from std_msgs.msg import Bool


class BumperNode(Node):
    """Reports bumper contact."""

    def __init__(self):
        super().__init__('bumper')
        self.create_publisher(Bool, 'bumper', 10)
        self.create_subscription(Bool, '/estop', self.on_estop, 10)

    def on_estop(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(BumperNode())
