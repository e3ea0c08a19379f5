from setuptools import setup

setup(
    name='chat_demo',
    packages=['chat_demo'],
    entry_points={'console_scripts': [
        'talker = chat_demo.talker:main',
        'listener = chat_demo.listener:main',
    ]},
)
