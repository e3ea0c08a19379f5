from setuptools import setup

package_name = 'py_comm_demo'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'adder_server = py_comm_demo.adder_server:main',
            'adder_client = py_comm_demo.adder_client:main',
            'fibonacci_server = py_comm_demo.fibonacci_server:main',
            'fibonacci_client = py_comm_demo.fibonacci_client:main',
            'lifecycle_talker = py_comm_demo.lifecycle_talker:main',
            'plain_node = py_comm_demo.plain_node:main',
        ],
    },
)
