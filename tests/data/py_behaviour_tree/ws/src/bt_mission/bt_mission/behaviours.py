"""Leaves of the mission tree. None of them has a ROS node until the tree is set up."""

import py_trees
from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import NavigateToPose
from rclpy.action import ActionClient
from sensor_msgs.msg import BatteryState
from std_srvs.srv import Trigger


class BatteryCheck(py_trees.behaviour.Behaviour):
    """Fails once the charge reported on its topic drops under a threshold."""

    def __init__(self, name, topic_name='battery_state', threshold=0.2):
        super().__init__(name=name)
        self.topic_name = topic_name
        self.threshold = threshold
        self.charge = 1.0
        self.node = None

    def setup(self, **kwargs):
        self.node = kwargs['node']
        self.node.create_subscription(BatteryState, self.topic_name, self.on_battery, 10)

    def on_battery(self, msg):
        self.charge = msg.percentage

    def update(self):
        if self.charge < self.threshold:
            return py_trees.common.Status.FAILURE
        return py_trees.common.Status.SUCCESS


class PublishGoal(py_trees.behaviour.Behaviour):
    """Publishes the goal pose of the robot it is built for."""

    def __init__(self, name, robot):
        super().__init__(name)
        self.robot = robot
        self.publisher = None

    def setup(self, **kwargs):
        node = kwargs.get('node')
        self.publisher = node.create_publisher(PoseStamped, f'{self.robot}/goal_pose', 10)

    def update(self):
        self.publisher.publish(PoseStamped())
        return py_trees.common.Status.SUCCESS


class NavigateTo(py_trees.behaviour.Behaviour):
    """Sends a NavigateToPose goal; the client is made on the first tick, not in setup."""

    def __init__(self, name, action_name='navigate_to_pose'):
        super().__init__(name)
        self.action_name = action_name
        self.client = None

    def setup(self, **kwargs):
        self.node = kwargs.get('node')

    def initialise(self):
        if self.client is None:
            self.client = ActionClient(self.node, NavigateToPose, self.action_name)
        self.client.send_goal_async(NavigateToPose.Goal())

    def update(self):
        return py_trees.common.Status.RUNNING


class CallTrigger(py_trees.behaviour.Behaviour):
    """Calls a Trigger service named '<prefix>/<verb>' once."""

    def __init__(self, name, prefix, verb):
        super().__init__(name)
        self.service_name = '{}/{}'.format(prefix, verb)
        self.client = None

    def setup(self, node, **kwargs):
        self.client = node.create_client(Trigger, self.service_name)

    def update(self):
        self.client.call_async(Trigger.Request())
        return py_trees.common.Status.SUCCESS
