import rclpy
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import Bool

ZONES = ['dock', 'gate']


class Watcher(Node):

    def __init__(self, zone):
        super().__init__(zone + '_watcher')
        self.create_subscription(Bool, zone + '/occupied', self.on_occupied, 1)

    def on_occupied(self, msg):
        pass


def main():
    rclpy.init()
    executor = MultiThreadedExecutor()
    for zone in ZONES:
        executor.add_node(Watcher(zone))
    executor.spin()
