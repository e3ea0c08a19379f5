import os
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import (EnvironmentVariable, LaunchConfiguration, PathJoinSubstitution,
                                  PythonExpression, TextSubstitution, ThisLaunchFileDir)
from launch_ros.substitutions import FindPackagePrefix, FindPackageShare

ROBOT = 'waffle'


def arg(name, value):
    return DeclareLaunchArgument(name, default_value=value)


def generate_launch_description():
    ns = LaunchConfiguration('ns')
    return LaunchDescription([
        arg('env', EnvironmentVariable('HOME', default_value='/root')),
        arg('prefix', FindPackagePrefix('demo')),
        arg('joined', PathJoinSubstitution([FindPackageShare('demo'), 'config', ROBOT + '.yaml'])),
        arg('eval', PythonExpression(['not ', ns, ' == "x"'])),
        arg('text', TextSubstitution(text='plain')),
        arg('fstring', f'{ROBOT}_{ns}'),
        arg('concat', [ns, '/cmd_vel']),
        arg('plus', 'robot_' + ROBOT),
        arg('percent', 'model_%s_%d' % (ROBOT, 3)),
        arg('format', '{}/{name}'.format(ROBOT, name='base')),
        arg('str', str(ROBOT) + str(2) + '\t'),
        arg('dir', os.path.join(os.path.dirname(__file__), 'params.yaml')),
        arg('env2', os.environ.get('MODEL', 'burger')),
        arg('env3', os.environ['LDS']),
        arg('this', ThisLaunchFileDir()),
        arg('unknown', some_module.compute(ns)),
        arg('join', '/'.join(['', ROBOT, 'base'])),
    ])
