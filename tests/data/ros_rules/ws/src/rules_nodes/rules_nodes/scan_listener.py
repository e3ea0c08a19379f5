import rclpy
from rclpy.node import Node

from sensor_msgs.msg import LaserScan


class ScanListener(Node):
    """Listens to a relative `scan` topic and nothing else."""

    def __init__(self):
        super().__init__('scan_listener')
        self.create_subscription(LaserScan, 'scan', self.on_scan, 10)

    def on_scan(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(ScanListener())
