from setuptools import setup

package_name = 'py_helper_demo'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'robot = py_helper_demo.robot:main',
            'scripted = py_helper_demo.scripted:main',
            'monitor_tool = py_helper_demo.monitor_tool:main',
        ],
    },
)
