from setuptools import setup

package_name = 'py_basic_demo'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    data_files=[('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'talker = py_basic_demo.talker:main',
            'listener = py_basic_demo.listener:main',
            'lambda_listener = py_basic_demo.lambda_listener:main',
            'old_school = py_basic_demo.old_school:main',
            'both = py_basic_demo.both:run',
        ],
    },
)
