from setuptools import setup

package_name = 'drive_py'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    entry_points={
        'console_scripts': [
            'battery_watch = drive_py.battery_watch:main',
            'relay_any = drive_py.relay_any:main',
        ],
    },
)
