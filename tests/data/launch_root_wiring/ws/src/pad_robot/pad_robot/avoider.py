import rclpy
from rclpy.node import Node

from sensor_msgs.msg import Range


class Avoider(Node):
    """Stops before obstacles; reads the simulated sensor by a relative name."""

    def __init__(self):
        super().__init__('avoider')
        self.range_sub = self.create_subscription(Range, 'sim/range', self.on_range, 10)

    def on_range(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Avoider())
