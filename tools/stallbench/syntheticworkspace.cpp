#include "syntheticworkspace.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>

namespace rosarch {

namespace {

bool write(const QString &path, const QString &text, QString *error)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(text.toUtf8()) < 0) {
        *error = QStringLiteral("cannot write %1: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

QString packageXml(const QString &name, bool cpp)
{
    return QStringLiteral(R"(<?xml version="1.0"?>
<package format="3">
  <name>%1</name>
  <version>0.1.0</version>
  <description>Generated package %1.</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <buildtool_depend>%2</buildtool_depend>
  <depend>std_msgs</depend>
  <export><build_type>%2</build_type></export>
</package>
)")
        .arg(name, cpp ? QStringLiteral("ament_cmake") : QStringLiteral("ament_python"));
}

} // namespace

bool SyntheticWorkspace::generate(const QString &root, int packages, int group, QString *error)
{
    bool ok = true;
    const auto write = [&](const QString &path, const QString &text) {
        ok = ok && ::rosarch::write(path, text, error);
    };
    for (int i = 0; i < packages; ++i) {
        const QString name = QStringLiteral("pkg_%1").arg(i, 4, 10, QLatin1Char('0'));
        const QString dir = root + QStringLiteral("/src/") + name;
        const bool cpp = i % 2 == 0;
        const QString out = QStringLiteral("topic_%1").arg(i);
        const QString in = QStringLiteral("topic_%1").arg(std::max(0, i - 1));
        write(dir + QStringLiteral("/package.xml"), packageXml(name, cpp));
        if (cpp) {
            write(dir + QStringLiteral("/CMakeLists.txt"),
                  QStringLiteral("cmake_minimum_required(VERSION 3.8)\nproject(%1)\n"
                                 "find_package(ament_cmake REQUIRED)\nfind_package(rclcpp "
                                 "REQUIRED)\nadd_executable(node src/node.cpp)\n"
                                 "install(TARGETS node DESTINATION lib/${PROJECT_NAME})\n"
                                 "ament_package()\n")
                      .arg(name));
            write(dir + QStringLiteral("/src/node.cpp"),
                  QStringLiteral(R"(#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

class Relay%1 : public rclcpp::Node
{
public:
  Relay%1() : Node("relay_%1")
  {
    pub_ = create_publisher<std_msgs::msg::String>("%2", 10);
    status_ = create_publisher<std_msgs::msg::String>("status", 10);
    sub_ = create_subscription<std_msgs::msg::String>(
      "%3", 10, [this](const std_msgs::msg::String & m) { pub_->publish(m); });
  }

private:
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_;
  rclcpp::Subscription<std_msgs::msg::String>::SharedPtr sub_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<Relay%1>());
  rclcpp::shutdown();
}
)")
                      .arg(i)
                      .arg(out, in));
        } else {
            write(dir + QStringLiteral("/setup.py"),
                  QStringLiteral("from setuptools import setup\n\nsetup(\n    name='%1',\n"
                                 "    packages=['%1'],\n    entry_points={'console_scripts': "
                                 "['node = %1.node:main']},\n)\n")
                      .arg(name));
            write(dir + QStringLiteral("/resource/") + name, {});
            write(dir + QLatin1Char('/') + name + QStringLiteral("/__init__.py"), {});
            write(dir + QLatin1Char('/') + name + QStringLiteral("/node.py"),
                  QStringLiteral(R"(import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Relay%1(Node):
    def __init__(self):
        super().__init__('relay_%1')
        self.pub = self.create_publisher(String, '%2', 10)
        self.status = self.create_publisher(String, 'status', 10)
        self.sub = self.create_subscription(String, '%3', self.pub.publish, 10)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Relay%1())
)")
                      .arg(i)
                      .arg(out, in));
        }
        QString launch = QStringLiteral("<launch>\n  <node pkg=\"%1\" exec=\"node\" "
                                        "name=\"relay_%2\"/>\n")
                             .arg(name)
                             .arg(i);
        if (i % group == 0)
            for (int k = i + 1; k < std::min(packages, i + group); ++k)
                launch += QStringLiteral("  <include file=\"$(find-pkg-share "
                                         "pkg_%1)/launch/pkg_%1.launch.xml\"/>\n")
                              .arg(k, 4, 10, QLatin1Char('0'));
        launch += QStringLiteral("</launch>\n");
        write(dir + QStringLiteral("/launch/") + name + QStringLiteral(".launch.xml"), launch);
    }
    QString all = QStringLiteral("<launch>\n");
    for (int i = 0; i < packages; i += group)
        all += QStringLiteral("  <include file=\"$(find-pkg-share "
                              "pkg_%1)/launch/pkg_%1.launch.xml\"/>\n")
                   .arg(i, 4, 10, QLatin1Char('0'));
    all += QStringLiteral("</launch>\n");
    write(root + QStringLiteral("/src/pkg_0000/launch/all.launch.xml"), all);
    return ok;
}

bool SyntheticWorkspace::generateLaunchFiles(const QString &root, int files, QString *error)
{
    const QString dir = root + QStringLiteral("/src/many_launch");
    bool ok = ::rosarch::write(dir + QStringLiteral("/package.xml"),
                               packageXml(QStringLiteral("many_launch"), false), error) &&
              ::rosarch::write(dir + QStringLiteral("/setup.py"),
                               QStringLiteral("from setuptools import setup\n\nsetup(name="
                                              "'many_launch', packages=['many_launch'], "
                                              "entry_points={'console_scripts': ['node = "
                                              "many_launch.node:main']})\n"),
                               error) &&
              ::rosarch::write(dir + QStringLiteral("/many_launch/__init__.py"), {}, error) &&
              ::rosarch::write(dir + QStringLiteral("/many_launch/node.py"),
                               QStringLiteral("from rclpy.node import Node\nfrom std_msgs.msg "
                                              "import String\n\n\nclass Relay(Node):\n    def "
                                              "__init__(self):\n        super().__init__('relay')"
                                              "\n        self.create_publisher(String, 'out', "
                                              "10)\n"),
                               error);
    for (int i = 0; ok && i < files; ++i) {
        const QString name = QStringLiteral("relay_%1").arg(i);
        const QString base = dir + QStringLiteral("/launch/l%1").arg(i, 5, 10, QLatin1Char('0'));
        switch (i % 3) {
        case 0:
            ok = ::rosarch::write(
                base + QStringLiteral(".launch.py"),
                QStringLiteral("from launch import LaunchDescription\nfrom launch_ros.actions "
                               "import Node\n\n\ndef generate_launch_description():\n    return "
                               "LaunchDescription([Node(package='many_launch', executable='node', "
                               "name='%1')])\n")
                    .arg(name),
                error);
            break;
        case 1:
            ok = ::rosarch::write(base + QStringLiteral(".launch.xml"),
                                  QStringLiteral("<launch>\n  <node pkg=\"many_launch\" "
                                                 "exec=\"node\" name=\"%1\"/>\n</launch>\n")
                                      .arg(name),
                                  error);
            break;
        default:
            ok = ::rosarch::write(base + QStringLiteral(".launch.yaml"),
                                  QStringLiteral("launch:\n- node: {pkg: many_launch, exec: node, "
                                                 "name: %1}\n")
                                      .arg(name),
                                  error);
        }
    }
    return ok;
}

} // namespace rosarch
