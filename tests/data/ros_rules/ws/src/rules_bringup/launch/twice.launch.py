# Rule: the same launch file included twice, each time under its own pushed namespace.
#
# Expected:
#   two parts typed by child.launch.py, one in namespace left and one in namespace right,
#   each carrying child's promoted `scan` port;
#   left/listener subscribes /left/scan, right/listener subscribes /right/scan;
#   no topic inside this file, and two boundary ports (one per included part).
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import PushRosNamespace
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    child = PathJoinSubstitution([FindPackageShare('rules_bringup'), 'launch', 'child.launch.py'])
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('left'),
            IncludeLaunchDescription(PythonLaunchDescriptionSource(child)),
        ]),
        GroupAction([
            PushRosNamespace('right'),
            IncludeLaunchDescription(PythonLaunchDescriptionSource(child)),
        ]),
    ])
