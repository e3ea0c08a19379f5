from setuptools import setup

package_name = 'cart_base'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/cart.launch.py', 'launch/sensors.launch.xml']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'odometry = cart_base.odometry:main',
            'safety = cart_base.safety:main',
            'bumper = cart_base.bumper:main',
            'recorder = cart_base.recorder:main',
        ],
    },
)
