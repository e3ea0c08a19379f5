from setuptools import setup

package_name = 'bt_mission'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'mission = bt_mission.mission:main',
        ],
    },
)
