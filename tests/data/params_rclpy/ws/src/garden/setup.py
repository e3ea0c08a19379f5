from setuptools import setup

package_name = 'garden'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    entry_points={
        'console_scripts': [
            'sprinkler = garden.sprinkler:main',
        ],
    },
)
