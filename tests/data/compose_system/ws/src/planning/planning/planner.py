import rclpy
from rclpy.action import ActionServer
from rclpy.node import Node

from geometry_msgs.msg import Twist
from planning_interfaces.action import Navigate
from std_msgs.msg import Empty
from std_srvs.srv import Trigger
from vision_msgs.msg import Detection2DArray


class Planner(Node):
    """Plans velocity commands from detections."""

    def __init__(self):
        super().__init__('planner')
        self.create_subscription(Detection2DArray, '/detections', self.on_detections, 10)
        self.cmd_pub = self.create_publisher(Twist, 'cmd_vel', 10)
        self.trigger_pub = self.create_publisher(Empty, 'front/trigger', 10)
        self.create_service(Trigger, 'replan', self.on_replan)
        self.server = ActionServer(self, Navigate, 'navigate', self.execute)

    def on_detections(self, msg):
        self.cmd_pub.publish(Twist())

    def on_replan(self, request, response):
        return response

    def execute(self, goal_handle):
        return Navigate.Result()


def main():
    rclpy.init()
    rclpy.spin(Planner())
