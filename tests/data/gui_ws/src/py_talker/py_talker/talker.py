import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    """Publishes a greeting and logs what comes back."""

    def __init__(self):
        super().__init__('talker')
        self.publisher = self.create_publisher(String, 'chatter', 10)
        self.subscription = self.create_subscription(String, 'echo', self.on_echo, 10)
        self.timer = self.create_timer(0.5, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = 'hello'
        self.publisher.publish(msg)

    def on_echo(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Talker())
    rclpy.shutdown()
