"""Watches the battery; declares its parameters one by one and as a group."""
import rclpy
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter
from sensor_msgs.msg import BatteryState


class BatteryWatch(Node):

    def __init__(self):
        super().__init__('battery_watch')
        self.declare_parameter('rate', 2.0)
        self.declare_parameter(
            'low_level', 0.2,
            ParameterDescriptor(
                description='Charge below which a warning is raised',
                floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]))
        self.declare_parameters(
            namespace='',
            parameters=[
                ('frame_id', 'battery'),
                ('cells', 4),
                ('thresholds', [0.1, 0.3], ParameterDescriptor(read_only=True)),
            ])
        self.declare_parameter('battery_topic', Parameter.Type.STRING)
        topic = self.get_parameter('battery_topic').value
        self.create_subscription(BatteryState, topic, self.on_state, 10)

    def on_state(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(BatteryWatch())
