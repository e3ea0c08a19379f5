# Rule: parameter files (wildcard key, namespaced node key, precedence over code defaults).
#
# One YAML file, two instances of the same node. Expected, this file analysed on its own:
#   cloud_maker       (namespace /)     output_topic = all_points  (from `/**`)
#                                       publishes /all_points
#                                       ~/stats inactive: enable_stats keeps its default false
#   left/cloud_maker  (namespace left)  output_topic = near_points (`left: cloud_maker:` wins)
#                                       publishes /left/near_points
#                                       serves /left/cloud_maker/stats (enable_stats: true)
# Nothing in this file consumes these ports, so all three active ones are promoted.
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('rules_bringup'), 'config', 'wildcards.yaml'])
    return LaunchDescription([
        Node(package='rules_nodes', executable='cloud_maker', name='cloud_maker',
             parameters=[params]),
        Node(package='rules_nodes', executable='cloud_maker', name='cloud_maker',
             namespace='left', parameters=[params]),
    ])
