import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import PushROSNamespace

ROBOTS = ['scout', 'hauler']


def generate_launch_description():
    stack = os.path.join(get_package_share_directory('robot_stack'), 'launch',
                         'stack.launch.py')
    actions = []
    for robot in ROBOTS:
        # Pushes the robot's namespace and passes it down as well: the stack pushes it again,
        # so its nodes run in /scout/scout.
        actions.append(GroupAction([
            PushROSNamespace(robot),
            IncludeLaunchDescription(PythonLaunchDescriptionSource(stack),
                                     launch_arguments={'robot': robot}.items()),
        ]))
    return LaunchDescription(actions)
