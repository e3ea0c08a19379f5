"""Waters the garden on a schedule; its parameters are declared with rclpy's calls."""
import rclpy
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter
from std_msgs.msg import Bool


class Sprinkler(Node):

    def __init__(self):
        super().__init__('sprinkler')
        self.declare_parameter('flow_rate', 1.5)
        self.declare_parameter('valve_count', Parameter.Type.INTEGER)
        self.declare_parameter(
            'moisture_threshold', 0.3,
            ParameterDescriptor(
                description='Soil moisture below which it waters',
                floating_point_range=[FloatingPointRange(from_value=0.0, to_value=1.0)]))
        self.declare_parameters(
            namespace='schedule',
            parameters=[
                ('start_hour', 6),
                ('days', ['mon', 'thu']),
                ('zone', 'lawn', ParameterDescriptor(read_only=True)),
            ])
        self.valve_pub = self.create_publisher(Bool, 'valve_open', 10)


def main():
    rclpy.init()
    rclpy.spin(Sprinkler())
