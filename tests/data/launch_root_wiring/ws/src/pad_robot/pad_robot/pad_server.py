import rclpy
from rclpy.node import Node

from sensor_msgs.msg import Joy


class PadServer(Node):
    """Reads the game pad and republishes it under the device namespace (relative name)."""

    def __init__(self):
        super().__init__('pad_server')
        self.joy_pub = self.create_publisher(Joy, 'device/joy', 10)


def main():
    rclpy.init()
    rclpy.spin(PadServer())
