import rclpy
from rclpy.node import Node

from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan


class Mapper(Node):
    """Builds the map from the scans."""

    def __init__(self):
        super().__init__('mapper')
        self.scan_sub = self.create_subscription(LaserScan, 'scan', self.on_scan, 10)
        self.map_pub = self.create_publisher(OccupancyGrid, 'map', 1)

    def on_scan(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Mapper())
