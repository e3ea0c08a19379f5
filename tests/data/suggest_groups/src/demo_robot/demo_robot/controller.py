import rclpy
from diagnostic_msgs.msg import DiagnosticArray
from geometry_msgs.msg import Twist
from nav_msgs.msg import Path
from rclpy.node import Node
from tf2_msgs.msg import TFMessage


class DecisionController(Node):
    """Follows the planned path by sending velocity commands."""

    def __init__(self):
        super().__init__('decision_controller')
        self.plan_sub = self.create_subscription(Path, 'plan', self.on_plan, 10)
        self.cmd_pub = self.create_publisher(Twist, 'cmd_vel', 10)
        self.tf_sub = self.create_subscription(TFMessage, '/tf', self.on_tf, 10)
        self.diag_pub = self.create_publisher(DiagnosticArray, '/diagnostics', 10)

    def on_plan(self, msg):
        pass

    def on_tf(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(DecisionController())
