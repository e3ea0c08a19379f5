from setuptools import setup

package_name = 'pad_robot'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/robot.launch.py', 'launch/avoidance.launch.xml']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'pad_server = pad_robot.pad_server:main',
            'drive = pad_robot.drive:main',
            'arm = pad_robot.arm:main',
            'range_sim = pad_robot.range_sim:main',
            'avoider = pad_robot.avoider:main',
        ],
    },
)
