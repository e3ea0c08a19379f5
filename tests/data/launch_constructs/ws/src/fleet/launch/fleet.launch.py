# Root: a loop over robots, a plain Python if, an OpaqueFunction and a later component load.
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, PushRosNamespace, SetRemap
from launch_ros.descriptions import ComposableNode

ROBOTS = ['alpha', 'beta']
USE_RELAY = True


def spawn_extra(context):
    return []


def generate_launch_description():
    share = get_package_share_directory('fleet')
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument('world', default_value='warehouse'))
    ld.add_action(DeclareLaunchArgument('operator'))
    for robot in ROBOTS:
        ld.add_action(GroupAction([
            PushRosNamespace(robot),
            SetRemap(src='/tf', dst='tf'),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(share, 'launch', 'robot.launch.xml')),
                launch_arguments={'name': robot, 'world': LaunchConfiguration('world')}.items()),
        ]))
    ld.add_action(ComposableNodeContainer(
        name='relays', namespace='', package='rclcpp_components',
        executable='component_container', composable_node_descriptions=[]))
    if USE_RELAY:
        ld.add_action(LoadComposableNodes(
            target_container='relays',
            composable_node_descriptions=[
                ComposableNode(package='fleet_nodes', plugin='fleet_nodes::Relay', name='relay')]))
    ld.add_action(OpaqueFunction(function=spawn_extra))
    ld.add_action(IncludeLaunchDescription(
        PythonLaunchDescriptionSource(os.path.join(
            get_package_share_directory('simulator_not_in_ws'), 'launch', 'sim.launch.py'))))
    return ld
