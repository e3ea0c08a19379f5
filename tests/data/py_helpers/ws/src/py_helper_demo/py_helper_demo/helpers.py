from geometry_msgs.msg import Twist
from std_msgs.msg import String
from std_srvs.srv import Trigger


class CommandRelay:
    """Creates its ports on the node it is given, not on itself."""

    def __init__(self, node, topic='cmd_vel'):
        self.node = node
        self.pub = self.node.create_publisher(Twist, topic, 10)

    def start(self):
        self.node.create_subscription(Twist, 'cmd_vel_in', self.relay, 10)

    def relay(self, msg):
        self.pub.publish(msg)


def add_diagnostics(node, name):
    node.create_publisher(String, name + '/diagnostics', 10)
    return node.create_service(Trigger, 'self_test', lambda request, response: response)
