import rclpy
from rclpy.node import Node

from sensor_msgs.msg import Joy


class Arm(Node):
    """Moves the arm from the pad; the launch file points its input at the absolute /device/joy."""

    def __init__(self):
        super().__init__('arm')
        self.joy_sub = self.create_subscription(Joy, 'joy', self.on_joy, 10)

    def on_joy(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Arm())
