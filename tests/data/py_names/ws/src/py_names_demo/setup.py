from setuptools import setup

package_name = 'py_names_demo'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'names = py_names_demo.names:main',
            'param_node = py_names_demo.param_node:main',
        ],
    },
)
