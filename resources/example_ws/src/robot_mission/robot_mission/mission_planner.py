"""Turns a list of delivery stops into navigation goals."""

import rclpy
from rclpy.action import ActionClient
from rclpy.node import Node
from robot_interfaces.action import Navigate
from robot_interfaces.msg import MissionStatus
from robot_interfaces.srv import SetMode
import sensor_msgs.msg


class TaskNode:
    """One stop of a mission: a tree of tasks, not a ROS node."""

    def __init__(self, name, children=()):
        self.name = name
        self.children = list(children)


class MissionPlanner(Node):
    """Sends the robot from stop to stop and reports mission progress."""

    def __init__(self):
        super().__init__('mission_planner')
        self.declare_parameter('battery_topic', 'battery_state')
        battery_topic = self.get_parameter('battery_topic').value
        status_topic = 'mission_status'

        self.status_pub = self.create_publisher(MissionStatus, status_topic, 10)
        self.battery_sub = self.create_subscription(
            sensor_msgs.msg.BatteryState, battery_topic, self.on_battery, 10)
        self.mode_client = self.create_client(SetMode, 'set_mode')
        self.navigate_client = ActionClient(self, Navigate, 'navigate')
        self.plan = TaskNode('delivery', [TaskNode('pickup'), TaskNode('dropoff')])

    def on_battery(self, msg):
        if msg.percentage < 0.2:
            self.get_logger().warn('battery low, returning to dock')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MissionPlanner())
    rclpy.shutdown()
