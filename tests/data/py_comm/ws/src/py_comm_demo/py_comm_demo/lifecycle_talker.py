import rclpy
from rclpy.lifecycle import LifecycleNode
from rclpy.lifecycle import TransitionCallbackReturn
from std_msgs.msg import String


class LifecycleTalker(LifecycleNode):

    def __init__(self, node_name, **kwargs):
        super().__init__(node_name, **kwargs)
        self._pub = None

    def on_configure(self, state):
        self._pub = self.create_lifecycle_publisher(String, 'lifecycle_chatter', 10)
        return TransitionCallbackReturn.SUCCESS


def main():
    rclpy.init()
    rclpy.spin(LifecycleTalker('lc_talker'))
