from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        ComposableNodeContainer(
            name='cloud_container',
            namespace='',
            package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(
                    package='depth_tools',
                    plugin='depth_tools::ShadedCloudNode',
                    name='shaded_cloud',
                    # The three inputs exist; the colour input was renamed to `shade` long
                    # ago and its remap is dead.
                    remappings=[('depth/image_rect', '/camera/depth/image_raw'),
                                ('shade/image_rect', '/camera/ir/image_raw'),
                                ('shade/camera_info', '/camera/ir/camera_info'),
                                ('color/image_rect', '/camera/color/image_raw'),
                                ('points', '/camera/points'),
                                ('preview/image_raw', '/camera/preview'),
                                ('preview/camera_info', '/camera/preview_info')],
                ),
            ],
        ),
    ])
