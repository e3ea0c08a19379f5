import rclpy
from rclpy.node import Node
from std_msgs.msg import String

from py_helper_demo.helpers import add_diagnostics, CommandRelay


class StatusWatcher:

    def __init__(self, owner):
        owner.create_subscription(String, 'status', self.on_status, 10)

    def on_status(self, msg):
        pass


class Robot(Node):

    def __init__(self):
        super().__init__('robot')
        self.relay = CommandRelay(self)
        self.relay.start()
        self.watcher = StatusWatcher(owner=self)
        add_diagnostics(self, 'robot')


def main():
    rclpy.init()
    rclpy.spin(Robot())
