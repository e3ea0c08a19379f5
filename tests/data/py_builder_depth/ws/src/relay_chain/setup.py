from setuptools import setup
setup(
    name='relay_chain',
    packages=['relay_chain'],
    entry_points={
        'console_scripts': [
            'chain = relay_chain.chain:main',
        ],
    },
)
