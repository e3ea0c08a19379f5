import rclpy
from std_msgs.msg import Header
from std_msgs.msg import String


class Registry:
    """Owns no node: subscribes on the node passed to one of its methods."""

    def watch(self, msg_type, topic, node):
        return node.create_subscription(msg_type, topic, self.on_message, 10)

    def on_message(self, msg):
        pass


class Worker:

    def run(self):
        self.node = rclpy.create_node('worker')
        self.registry = Registry()
        self.registry.watch(Header, 'heartbeat', self.node)
        self.node.create_publisher(String, 'worker_status', 10)


def main():
    rclpy.init()
    probe = rclpy.create_node('probe')
    Worker().run()
    rclpy.spin(probe)
