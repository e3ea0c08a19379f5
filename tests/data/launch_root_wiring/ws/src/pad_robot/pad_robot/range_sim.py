import rclpy
from rclpy.node import Node

from sensor_msgs.msg import Range


class RangeSim(Node):
    """A simulated range sensor, publishing under an absolute name."""

    def __init__(self):
        super().__init__('range_sim')
        self.range_pub = self.create_publisher(Range, '/sim/range', 10)


def main():
    rclpy.init()
    rclpy.spin(RangeSim())
