from launch import LaunchDescription
from launch.conditions import IfCondition, LaunchConfigurationEquals, LaunchConfigurationNotEquals, UnlessCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='p', executable='a', condition=IfCondition(LaunchConfiguration('use_a'))),
        Node(package='p', executable='b', condition=UnlessCondition(PythonExpression(["'", LaunchConfiguration('mode'), "' == 'sim'"]))),
        Node(package='p', executable='c', condition=LaunchConfigurationEquals('mode', 'real')),
        Node(package='p', executable='d', condition=LaunchConfigurationNotEquals('mode', 'real')),
        Node(package='p', executable='e', condition=custom_condition),
    ])
