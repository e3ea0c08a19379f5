import rclpy
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from geometry_msgs.msg import PoseWithCovarianceStamped
from nav_msgs.msg import OccupancyGrid, Odometry
from sensor_msgs.msg import LaserScan


class Mapper(Node):
    """Builds an occupancy grid from scans and odometry."""

    def __init__(self):
        super().__init__('mapper')
        # Asks for reliable delivery of scans that are only offered best effort.
        self.create_subscription(
            LaserScan, 'scan', self.on_scan,
            QoSProfile(depth=5, reliability=ReliabilityPolicy.RELIABLE))
        # A typo: the lidar publishes 'wheel_odom'.
        self.create_subscription(Odometry, 'whel_odom', self.on_odom, 10)
        self.create_subscription(PoseWithCovarianceStamped, 'initialpose', self.on_pose, 10)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.map_pub = self.create_publisher(OccupancyGrid, 'map', latched)

    def on_scan(self, msg):
        pass

    def on_odom(self, msg):
        pass

    def on_pose(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Mapper())
