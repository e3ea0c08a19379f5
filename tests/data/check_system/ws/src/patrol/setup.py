from setuptools import setup

package_name = 'patrol'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/patrol.launch.py']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'lidar = patrol.lidar:main',
            'mapper = patrol.mapper:main',
            'viewer = patrol.viewer:main',
            'teleop = patrol.teleop:main',
        ],
    },
)
