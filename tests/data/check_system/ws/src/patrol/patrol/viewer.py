import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data

from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan


class Viewer(Node):
    """Shows the map and the latest scan."""

    def __init__(self):
        super().__init__('viewer')
        self.create_subscription(LaserScan, 'scan', self.on_scan, qos_profile_sensor_data)
        # A volatile request is served by the mapper's transient-local offer.
        self.create_subscription(OccupancyGrid, 'map', self.on_map, 1)

    def on_scan(self, msg):
        pass

    def on_map(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Viewer())
