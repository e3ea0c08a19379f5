import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    sim = get_package_share_directory('nav2_minimal_tb3_sim')
    share = get_package_share_directory('sim_bringup')
    return LaunchDescription([
        # A launch file of a package outside the workspace: its interface model gives the
        # simulated robot's sensors and velocity input, under the namespace passed to it.
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(sim, 'launch', 'spawn_tb3.launch.py')),
            launch_arguments={'namespace': 'robot1'}.items()),
        GroupAction([
            PushRosNamespace('robot1'),
            Node(package='sim_bringup', executable='follower'),
            Node(package='robot_state_publisher', executable='robot_state_publisher'),
        ]),
        # RViz at the root publishes /goal_pose, not the robot's /robot1/goal_pose; it
        # subscribes to what its configuration displays.
        Node(package='rviz2', executable='rviz2',
             arguments=['-d', os.path.join(share, 'rviz', 'sim.rviz')]),
    ])
