import launch
import launch_ros.actions


def generate_launch_description():
    talker = launch_ros.actions.Node(package='demo', executable='talker')
    nodes = [talker]
    nodes.append(launch_ros.actions.Node(package='demo', executable='listener'))
    nodes.extend([launch_ros.actions.Node(package='demo', executable='relay')])
    nodes += [launch_ros.actions.Node(package='demo', executable='echo')]
    args = [launch.actions.DeclareLaunchArgument('a'), launch.actions.DeclareLaunchArgument('b', default_value='1')]
    ld = launch.LaunchDescription([*args])
    for node in nodes:
        ld.add_action(node)
    ld.add_action(launch.actions.LogInfo(msg='hello'))
    return ld
