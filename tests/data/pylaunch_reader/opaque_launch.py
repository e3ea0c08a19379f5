from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def launch_setup(context, *args, **kwargs):
    ns = context.launch_configurations['namespace']
    model = LaunchConfiguration('model').perform(context)
    rate = context.launch_configurations.get('rate', '10')
    nodes = [Node(package='p', executable='a', namespace=ns, parameters=[{'model': model, 'rate': rate}])]
    if model == 'burger':
        nodes.append(Node(package='p', executable='burger_only'))
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('model', default_value='burger'),
        OpaqueFunction(function=launch_setup),
        OpaqueFunction(function=undefined_elsewhere),
    ])
