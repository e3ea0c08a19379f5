from launch import LaunchDescription
from launch.actions import (ExecuteProcess, LogInfo, RegisterEventHandler, SetEnvironmentVariable,
                            TimerAction)
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    spawner = Node(package='controller_manager', executable='spawner', arguments=['joint_state_broadcaster'])
    rviz = Node(package='rviz2', executable='rviz2')
    return LaunchDescription([
        SetEnvironmentVariable('RCUTILS_COLORIZED_OUTPUT', '1'),
        LogInfo(msg='starting'),
        ExecuteProcess(cmd=['ros2', 'bag', 'record', '-a']),
        spawner,
        RegisterEventHandler(OnProcessExit(target_action=spawner, on_exit=[rviz])),
        TimerAction(period=2.0, actions=[Node(package='late', executable='starter')]),
        make_custom_action(),
    ])
