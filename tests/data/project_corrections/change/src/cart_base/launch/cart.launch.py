from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    sensors = PathJoinSubstitution([FindPackageShare('cart_base'), 'launch', 'sensors.launch.xml'])
    return LaunchDescription([
        Node(package='cart_base', executable='arbiter', name='arbiter'),
        Node(package='cart_base', executable='odometry', name='odometry'),
        Node(package='cart_base', executable='safety', name='safety_supervisor'),
        Node(package='cart_base', executable='recorder', name='recorder'),
        GroupAction([
            PushRosNamespace('sensors'),
            IncludeLaunchDescription(AnyLaunchDescriptionSource(sensors)),
        ]),
    ])
