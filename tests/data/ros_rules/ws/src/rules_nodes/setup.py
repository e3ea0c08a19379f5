from setuptools import setup

package_name = 'rules_nodes'

# Every executable of the fixture is built here; other_pkg.launch.py starts `teleop`
# under the name of rules_bringup, which builds none.
setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'cloud_maker = rules_nodes.cloud_maker:main',
            'cmd_relay = rules_nodes.cmd_relay:main',
            'teleop = rules_nodes.teleop:main',
            'scan_listener = rules_nodes.scan_listener:main',
        ],
    },
)
