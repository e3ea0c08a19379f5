from setuptools import setup

package_name = 'py_inherit_demo'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'battery = py_inherit_demo.battery:main',
            'temperature = py_inherit_demo.temperature:main',
        ],
    },
)
