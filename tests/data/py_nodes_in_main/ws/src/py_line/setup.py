from setuptools import setup
setup(
    name='py_line',
    packages=['py_line'],
    entry_points={
        'console_scripts': [
            'watchers = py_line.watchers:main',
            'line = py_line.line:main',
        ],
    },
)
