from setuptools import setup

package_name = 'sim_bringup'

setup(
    name=package_name,
    version='0.3.0',
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/sim.launch.py']),
        ('share/' + package_name + '/rviz', ['rviz/sim.rviz']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'follower = sim_bringup.follower:main',
        ],
    },
)
