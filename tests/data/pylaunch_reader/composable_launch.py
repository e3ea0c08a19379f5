from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.descriptions import ComposableNode
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    ns = LaunchConfiguration('namespace')
    container = ComposableNodeContainer(
        name='my_container', namespace=ns, package='rclcpp_components', executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='composition', plugin='composition::Talker', name='talker',
                           remappings=[('chatter', 'talk')], parameters=[{'rate': 2}],
                           extra_arguments=[{'use_intra_process_comms': True}]),
        ])
    load_by_name = LoadComposableNodes(
        target_container=(ns, '/', 'my_container'),
        composable_node_descriptions=[ComposableNode(package='composition', plugin='composition::Listener', name='listener')])
    load_by_object = LoadComposableNodes(target_container=container, composable_node_descriptions=[
        ComposableNode(package='composition', plugin='composition::Server', namespace='srv')])
    return LaunchDescription([container, load_by_name, load_by_object])
