from setuptools import find_packages, setup

package_name = 'demo_robot'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    entry_points={
        'console_scripts': [
            'vision_camera = demo_robot.camera:main',
            'vision_detector = demo_robot.detector:main',
            'vision_tracker = demo_robot.tracker:main',
            'decision_planner = demo_robot.planner:main',
            'decision_controller = demo_robot.controller:main',
            'tf_broadcaster = demo_robot.tf_broadcaster:main',
            'status_reporter = demo_robot.status_reporter:main',
        ],
    },
)
