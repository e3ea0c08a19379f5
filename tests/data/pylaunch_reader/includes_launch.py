import os
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.substitutions import FindPackageShare

LAUNCH_DIR = os.path.join(get_package_share_directory('nav2_bringup'), 'launch')


def generate_launch_description():
    use_rviz = LaunchConfiguration('use_rviz')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(os.path.join(LAUNCH_DIR, 'rviz_launch.py')),
                                 launch_arguments={'namespace': 'robot1', 'use_sim_time': True}.items(),
                                 condition=IfCondition(use_rviz)),
        IncludeLaunchDescription(PythonLaunchDescriptionSource([ThisLaunchFileDir(), '/state_publisher.launch.py']),
                                 launch_arguments=[('model', 'burger')]),
        IncludeLaunchDescription(XMLLaunchDescriptionSource(PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'x.launch.xml'])),
                                 launch_arguments=dict(a='1', b=use_rviz).items()),
        IncludeLaunchDescription(AnyLaunchDescriptionSource('/opt/ros/y.launch.yaml')),
        IncludeLaunchDescription('/plain/path_launch.py'),
    ])
