import rclpy
import rclpy.node
from std_msgs.msg import String as Text


class Listener(rclpy.node.Node):
    """Old-style super call, aliased message type."""

    def __init__(self):
        super(Listener, self).__init__('listener')
        self.sub = self.create_subscription(Text, 'chatter', self.on_text, 10)

    def on_text(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    node = Listener()
    rclpy.spin(node)
