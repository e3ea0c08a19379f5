import rclpy
from rclpy.node import Node

from sensor_msgs.msg import LaserScan, PointCloud2
from std_msgs.msg import Float64
from visualization_msgs.msg import MarkerArray


class Lidar(Node):
    """Publishes scans, and outputs for tools: markers, a debug cloud and its processing time."""

    def __init__(self):
        super().__init__('lidar')
        self.scan_pub = self.create_publisher(LaserScan, 'scan', 10)
        # Nobody subscribes to the raw scan: a real finding.
        self.raw_pub = self.create_publisher(LaserScan, 'scan_raw', 10)
        # For RViz, by message package.
        self.marker_pub = self.create_publisher(MarkerArray, 'scan_outline', 1)
        # For tools, by name: a debug namespace and a processing time.
        self.cloud_pub = self.create_publisher(PointCloud2, '~/debug/cloud', 1)
        self.time_pub = self.create_publisher(Float64, '~/processing_time_ms', 1)


def main():
    rclpy.init()
    rclpy.spin(Lidar())
