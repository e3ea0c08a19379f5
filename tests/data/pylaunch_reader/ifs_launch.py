import os
from launch import LaunchDescription
from launch_ros.actions import Node

USE_SIM = True
MODEL = 'burger'


def generate_launch_description():
    ld = LaunchDescription()
    if USE_SIM and MODEL == 'burger':
        ld.add_action(Node(package='sim', executable='decided'))
    else:
        ld.add_action(Node(package='sim', executable='never'))
    if os.environ.get('ROBOT') == 'real':
        ld.add_action(Node(package='hw', executable='driver'))
        ld.add_action(Node(package='hw', executable='imu'))
    elif MODEL in ['waffle', 'burger']:
        ld.add_action(Node(package='sim', executable='fake'))
    else:
        ld.add_action(Node(package='sim', executable='other'))
    return ld
