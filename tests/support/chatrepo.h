#pragma once

// A git repository with two revisions of a small workspace, made by the test: HEAD~1 has a
// speaker publishing /chatter and a hearer subscribing to it; HEAD renames the topic to /chat
// in both and gives the hearer a second subscription, to /clock. Used by the diff tests.
#include "support/testsupport.h"

namespace rosarch::test::chat {

using rosarch::test::writeFile;

inline const char *const kPackageXml = R"(<?xml version="1.0"?>
<package format="3">
  <name>chat</name>
  <version>0.1.0</version>
  <description>Two nodes that talk.</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <export><build_type>ament_python</build_type></export>
</package>
)";

inline const char *const kSetupPy = R"(from setuptools import setup

setup(
    name='chat',
    packages=['chat'],
    entry_points={'console_scripts': [
        'speaker = chat.speaker:main',
        'hearer = chat.hearer:main',
    ]},
)
)";

inline const char *const kLaunch = R"(from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='chat', executable='speaker', name='speaker'),
        Node(package='chat', executable='hearer', name='hearer'),
    ])
)";

inline QByteArray speaker(const char *topic)
{
    return QByteArray(R"(from rclpy.node import Node
from std_msgs.msg import String


class Speaker(Node):
    def __init__(self):
        super().__init__('speaker')
        self.pub = self.create_publisher(String, ')") +
           topic + R"(', 10)


def main():
    Speaker()
)";
}

inline QByteArray hearer(const char *topic, bool clock)
{
    QByteArray text = QByteArray(R"(from rclpy.node import Node
from rosgraph_msgs.msg import Clock
from std_msgs.msg import String


class Hearer(Node):
    def __init__(self):
        super().__init__('hearer')
        self.create_subscription(String, ')") +
                      topic + "', self.on_text, 10)\n";
    if (clock)
        text += "        self.create_subscription(Clock, 'clock', self.on_clock, 10)\n";
    return text + R"(
    def on_text(self, msg):
        pass

    def on_clock(self, msg):
        pass


def main():
    Hearer()
)";
}

inline void writeWorkspace(const QString &root, const char *topic, bool clock)
{
    const QDir pkg(QDir(root).filePath(QStringLiteral("ws/src/chat")));
    writeFile(pkg.filePath(QStringLiteral("package.xml")), kPackageXml);
    writeFile(pkg.filePath(QStringLiteral("setup.py")), kSetupPy);
    writeFile(pkg.filePath(QStringLiteral("chat/__init__.py")), "");
    writeFile(pkg.filePath(QStringLiteral("chat/speaker.py")), speaker(topic));
    writeFile(pkg.filePath(QStringLiteral("chat/hearer.py")), hearer(topic, clock));
    writeFile(pkg.filePath(QStringLiteral("launch/chat.launch.py")), kLaunch);
}

inline bool git(const QString &dir, const QStringList &args)
{
    QProcess p;
    p.setWorkingDirectory(dir);
    p.start(QStringLiteral("git"),
            QStringList{QStringLiteral("-c"), QStringLiteral("user.name=rosarch test"),
                        QStringLiteral("-c"), QStringLiteral("user.email=test@example.com")} +
                args);
    return p.waitForFinished(30000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0;
}

/// Creates the repository in `root` (its workspace is `root`/ws); false when git fails.
inline bool createRepository(const QString &root)
{
    writeWorkspace(root, "chatter", false);
    if (!git(root, {QStringLiteral("init"), QStringLiteral("-q")}) ||
        !git(root, {QStringLiteral("add"), QStringLiteral(".")}) ||
        !git(root, {QStringLiteral("commit"), QStringLiteral("-qm"), QStringLiteral("v1")}))
        return false;
    writeWorkspace(root, "chat", true);
    return git(root, {QStringLiteral("commit"), QStringLiteral("-qam"),
                      QStringLiteral("v2: rename chatter, hear the clock")});
}

} // namespace rosarch::test::chat
