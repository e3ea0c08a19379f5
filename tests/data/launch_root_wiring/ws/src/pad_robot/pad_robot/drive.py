import rclpy
from rclpy.node import Node

from sensor_msgs.msg import Joy


class Drive(Node):
    """Drives from the pad; the launch file points its input at the absolute /device/joy."""

    def __init__(self):
        super().__init__('drive')
        self.joy_sub = self.create_subscription(Joy, 'joy', self.on_joy, 10)

    def on_joy(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Drive())
