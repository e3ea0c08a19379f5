# Rule: a parameter file rewritten by nav2_common's RewrittenYaml.
#
# base.yaml says `cloud_maker: output_topic: base_points` with no namespace key.
# root_key moves that entry under the `namespace` argument (default robot), so it matches
# /robot/cloud_maker; param_rewrites then replaces base_points with rewritten_points.
# Expected, with the default argument:
#   robot/cloud_maker  publishes /robot/rewritten_points  (not base_points, not points)
#                      serves /robot/cloud_maker/stats     (enable_stats: true from base.yaml)
# Both ports are promoted (nothing else in this file).
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    base_params = os.path.join(get_package_share_directory('rules_bringup'), 'config', 'base.yaml')
    configured_params = RewrittenYaml(
        source_file=base_params,
        root_key=namespace,
        param_rewrites={'output_topic': 'rewritten_points'},
        convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='robot',
                              description='Namespace of the node and root key of its parameters'),
        Node(package='rules_nodes', executable='cloud_maker', name='cloud_maker',
             namespace=namespace, parameters=[configured_params]),
    ])
