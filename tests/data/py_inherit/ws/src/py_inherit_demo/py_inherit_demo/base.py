from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


class MonitorBase(Node):
    """Project base class: every monitor reports a status and can be reset."""

    def __init__(self, name, status_topic='status'):
        super().__init__(name)
        self.status_pub = self.create_publisher(String, status_topic, 10)
        self.reset_srv = self.create_service(Trigger, 'reset', self.on_reset)
        self.setup()

    def setup(self):
        self.heartbeat = self.create_publisher(String, 'heartbeat', 1)

    def on_reset(self, request, response):
        return response


class EstopMixin:
    """Not a node by itself; adds a port to the node it is mixed into."""

    def add_estop(self):
        self.create_subscription(String, 'estop', self.on_estop, 1)

    def on_estop(self, msg):
        pass
