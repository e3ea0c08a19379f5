// The window on a large workspace (1,000 packages, generated): the stages run, the result
// arrives in the views, the status bar says which stage is at how many files, the log says how
// long each stage took, and the UI thread never stops answering for long (a generous limit
// here; rosarch-stallbench measures it strictly on real workspaces).
#include "atomicnodemodel.h"
#include "document.h"
#include "launchtreemodel.h"
#include "logview.h"
#include "mainwindow.h"
#include "stagerunner.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace rosarch;

namespace {

constexpr int kPackages = 1000;
constexpr int kGroup = 10; ///< every 10th package's launch file includes the next nine

#if defined(__SANITIZE_ADDRESS__)
constexpr qint64 kStallLimitMs = 10000; // AddressSanitizer makes everything several times slower
#else
constexpr qint64 kStallLimitMs = 2000;
#endif

void write(const QString &path, const QString &text)
{
    QDir().mkpath(QFileInfo(path).path());
    QFile f(path);
    QVERIFY2(f.open(QIODevice::WriteOnly | QIODevice::Truncate), qPrintable(path));
    f.write(text.toUtf8());
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

/// Package i: a C++ node (even i) or a Python node (odd i) publishing topic_i and subscribing
/// to topic_{i-1}, and a launch file starting it; every kGroup-th package's launch file also
/// includes the next packages' launch files, and package 0 has all.launch.xml including the
/// groups.
void generate(const QString &root)
{
    for (int i = 0; i < kPackages; ++i) {
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
        if (i % kGroup == 0)
            for (int k = i + 1; k < std::min(kPackages, i + kGroup); ++k)
                launch += QStringLiteral("  <include file=\"$(find-pkg-share "
                                         "pkg_%1)/launch/pkg_%1.launch.xml\"/>\n")
                              .arg(k, 4, 10, QLatin1Char('0'));
        launch += QStringLiteral("</launch>\n");
        write(dir + QStringLiteral("/launch/") + name + QStringLiteral(".launch.xml"), launch);
    }
    QString all = QStringLiteral("<launch>\n");
    for (int i = 0; i < kPackages; i += kGroup)
        all += QStringLiteral("  <include file=\"$(find-pkg-share "
                              "pkg_%1)/launch/pkg_%1.launch.xml\"/>\n")
                   .arg(i, 4, 10, QLatin1Char('0'));
    all += QStringLiteral("</launch>\n");
    write(root + QStringLiteral("/src/pkg_0000/launch/all.launch.xml"), all);
}

/// The longest time the UI thread did not get to a 10 ms timer while it was watched.
class StallWatch
{
public:
    StallWatch()
    {
        m_clock.start();
        m_timer.setInterval(10);
        QObject::connect(&m_timer, &QTimer::timeout, [this] {
            const qint64 now = m_clock.elapsed();
            m_longest = std::max(m_longest, now - m_last);
            m_last = now;
        });
        m_timer.start();
    }
    qint64 longest() const { return m_longest; }

private:
    QElapsedTimer m_clock;
    QTimer m_timer;
    qint64 m_last = 0;
    qint64 m_longest = 0;
};

} // namespace

class TestLargeWorkspace : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                 .filePath(QStringLiteral("projects")))
            .removeRecursively();
    }

    void aThousandPackagesArriveWithoutFreezingTheWindow()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        // kept for rosarch-stallbench when asked
        dir.setAutoRemove(qEnvironmentVariableIsEmpty("ROSARCH_KEEP_LARGE_WORKSPACE"));
        generate(dir.path());
        if (!dir.autoRemove())
            qInfo("workspace kept in %s", qPrintable(dir.path()));
        if (QTest::currentTestFailed())
            return;

        MainWindow w;
        w.resize(1400, 900);
        w.show();
        QStringList statusMessages;
        connect(w.statusBar(), &QStatusBar::messageChanged, this,
                [&](const QString &m) { statusMessages << m; });
        QSignalSpy finished(w.runner(), &StageRunner::stageFinished);
        QSignalSpy progressed(w.runner(), &StageRunner::stageProgressed);
        QSignalSpy timed(w.runner(), &StageRunner::stageTimed);
        StallWatch watch;
        w.openWorkspace(dir.path());
        QVERIFY(finished.wait(120000));
        QTest::qWait(300); // what the result sets off (diagram, views) runs

        // The result arrived, in the document and in the views.
        const AtomicNodeList &nodes = w.document()->atomicNodes();
        QCOMPARE(nodes.nodes.size(), kPackages);
        QCOMPARE(w.nodeModel()->rowCount(), kPackages); // one package row each
        const QModelIndex relay = w.nodeModel()->nodeIndex(nodes.nodes.first().id);
        QVERIFY(relay.isValid());
        QCOMPARE(w.nodeModel()->rowCount(relay), 3); // two publishers, one subscription
        const LaunchDependencies &launch = w.document()->launchDependencies();
        QCOMPARE(launch.launchFiles.size(), kPackages + 1);
        QVERIFY2(launch.nodes.size() >= kPackages,
                 qPrintable(QString::number(launch.nodes.size())));
        QVERIFY(w.launchModel()->rowCount() > 0);

        // Per-stage progress with file counts, and the time each stage took, in the log.
        QSet<int> stages;
        for (const QList<QVariant> &p : std::as_const(progressed))
            if (p.at(1).toInt() > 0)
                stages.insert(p.at(3).toInt());
        QVERIFY(stages.contains(1));
        QVERIFY(stages.contains(2));
        QVERIFY(stages.contains(3));
        QVERIFY2(std::any_of(statusMessages.cbegin(), statusMessages.cend(),
                             [](const QString &m) {
                                 return m.startsWith(QStringLiteral("Stage 1: atomic nodes — ")) &&
                                        m.endsWith(QStringLiteral(" files"));
                             }),
                 qPrintable(statusMessages.join(u'\n')));
        QCOMPARE(timed.size(), 3);
        const QString log = w.logView()->logEdit()->toPlainText();
        for (const QString &line : {QStringLiteral("Stage 1 (atomic nodes) took "),
                                    QStringLiteral("Stage 2 (launch files) took "),
                                    QStringLiteral("Stage 3 (composition) took "),
                                    QStringLiteral("Showing the result in the window took ")})
            QVERIFY2(log.contains(line), qPrintable(line));

        // A second run finds nothing new: the views stay.
        QTest::keyClick(&w, Qt::Key_F5);
        QVERIFY(finished.wait(120000));
        QVERIFY(w.runner()->resultUnchanged());
        QCOMPARE(w.nodeModel()->rowCount(), kPackages);
        QVERIFY(w.logView()->logEdit()->toPlainText().contains(
            QStringLiteral("the result is the same as the one shown")));
        QTest::qWait(100);

        QVERIFY2(
            watch.longest() < kStallLimitMs,
            qPrintable(QStringLiteral("the UI thread stalled for %1 ms").arg(watch.longest())));
    }
};

QTEST_MAIN(TestLargeWorkspace)
#include "tst_largeworkspace.moc"
