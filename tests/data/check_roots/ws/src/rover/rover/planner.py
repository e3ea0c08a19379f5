import rclpy
from rclpy.node import Node

from nav_msgs.msg import OccupancyGrid, Odometry


class Planner(Node):
    """Plans on a map that no launch file of this workspace provides."""

    def __init__(self):
        super().__init__('planner')
        self.map_sub = self.create_subscription(OccupancyGrid, 'map', self.on_map, 1)
        self.odom_sub = self.create_subscription(Odometry, 'odom', self.on_odom, 10)
        # A typo: the odometry node publishes 'odom_raw'.
        self.raw_sub = self.create_subscription(Odometry, 'odom_raws', self.on_odom, 10)

    def on_map(self, msg):
        pass

    def on_odom(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Planner())
