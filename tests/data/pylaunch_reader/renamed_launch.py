# Parameters rewritten on the way in (nav2_common's RewrittenYaml), and nodes renamed by
# command-line remap rules instead of name= / namespace=.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = os.path.join(get_package_share_directory('planner_bringup'), 'config', 'p.yaml')
    overrides = {'use_sim_time': LaunchConfiguration('sim'), 'rate': '5'}
    rewritten = ParameterFile(
        RewrittenYaml(source_file=params, root_key=LaunchConfiguration('robot'),
                      param_rewrites=overrides, value_rewrites={'ZONE': 'on'},
                      convert_types=True),
        allow_substs=True)
    return LaunchDescription([
        Node(package='planner', executable='plan', parameters=[rewritten],
             arguments=['--ros-args', '-r', '__node:=global_planner', '-r', '__ns:=/nav']),
        Node(package='planner', executable='plan', name='kept',
             remappings=[('__node', 'ignored'), ('__ns', '/fleet'), ('map', '/map')]),
    ])
