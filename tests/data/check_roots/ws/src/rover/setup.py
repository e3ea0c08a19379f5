from setuptools import setup

package_name = 'rover'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/planning.launch.py', 'launch/sim.launch.py',
                                               'launch/field.launch.py', 'launch/fleet.launch.py',
                                               'launch/nav.launch.py']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'planner = rover.planner:main',
            'odometry = rover.odometry:main',
        ],
    },
)
