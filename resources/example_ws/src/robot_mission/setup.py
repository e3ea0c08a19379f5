from setuptools import find_packages, setup

package_name = 'robot_mission'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='rosarch',
    description='Mission planning and monitoring of the example delivery robot.',
    license='GPL-3.0-or-later',
    entry_points={
        'console_scripts': [
            'mission_planner = robot_mission.mission_planner:main',
            'mode_manager = robot_mission.mode_manager:main',
            f'battery_monitor = {package_name}.battery_monitor:main',
            'heartbeat = ' + package_name + '.heartbeat:main',
        ],
    },
)
