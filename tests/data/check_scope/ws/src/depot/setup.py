from setuptools import setup

package_name = 'depot'

setup(
    name=package_name,
    version='1.2.0',
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/robot.launch.xml', 'launch/mapping.launch.py',
                                               'launch/lone.launch.py']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'lidar = depot.lidar:main',
            'mapper = depot.mapper:main',
            'planner = depot.planner:main',
        ],
    },
)
