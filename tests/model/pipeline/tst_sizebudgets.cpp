// Budgets on sizes, not only counts: a value that evaluation builds stops at the
// size budget with an evaluation-limit diagnostic at its file and line; the rest of the
// workspace is recovered. Each workspace is generated here, next to a healthy node.
#include "core/editdistance.h"
#include "core/valuebudget.h"
#include "pipeline/recovery.h"
#include "support/recoverytest.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using test::writeFile;

namespace {

/// "file:line" of every diagnostic with this code, in all three stages.
QStringList placesOf(const Recovery &r, const QString &code)
{
    QStringList out;
    for (const QList<Diagnostic> *list :
         {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics})
        for (const Diagnostic &d : *list)
            if (d.code == code)
                out << QStringLiteral("%1:%2").arg(d.evidence.file).arg(d.evidence.line);
    return out;
}

const NodeInstance *instance(const Recovery &r, const QString &name)
{
    for (const NodeInstance &n : r.launch.nodes)
        if (n.nodeName == name)
            return &n;
    return nullptr;
}

/// 26 arguments, each the previous one twice (2^26 characters at the end), the last used as
/// the namespace of `good`: in XML, YAML or Python.
QByteArray doublingLaunchFile(const QString &format)
{
    QByteArray out;
    if (format == QLatin1String("xml")) {
        out = "<launch>\n  <arg name=\"a0\" default=\"ab\"/>\n";
        for (int i = 1; i < 26; ++i)
            out += QStringLiteral("  <arg name=\"a%1\" default=\"$(var a%2)$(var a%2)\"/>\n")
                       .arg(i)
                       .arg(i - 1)
                       .toUtf8();
        return out + "  <node pkg=\"pkg\" exec=\"good\" name=\"good\" namespace=\"$(var a25)\"/>\n"
                     "</launch>\n";
    }
    if (format == QLatin1String("yaml")) {
        out = "launch:\n- arg: {name: a0, default: ab}\n";
        for (int i = 1; i < 26; ++i)
            out += QStringLiteral("- arg: {name: a%1, default: \"$(var a%2)$(var a%2)\"}\n")
                       .arg(i)
                       .arg(i - 1)
                       .toUtf8();
        return out + "- node: {pkg: pkg, exec: good, name: good, namespace: \"$(var a25)\"}\n";
    }
    out = "from launch import LaunchDescription\nfrom launch.actions import DeclareLaunchArgument\n"
          "from launch.substitutions import LaunchConfiguration as C\n"
          "from launch_ros.actions import Node\n\ndef generate_launch_description():\n"
          "    ld = [DeclareLaunchArgument('a0', default_value='ab')]\n";
    for (int i = 1; i < 26; ++i)
        out += QStringLiteral("    ld.append(DeclareLaunchArgument('a%1', default_value=[C('a%2'), "
                              "C('a%2')]))\n")
                   .arg(i)
                   .arg(i - 1)
                   .toUtf8();
    return out + "    ld.append(Node(package='pkg', executable='good', name='good', "
                 "namespace=C('a25')))\n    return LaunchDescription(ld)\n";
}

} // namespace

class TestSizeBudgets : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void aCMakeVariableDoubledInALoopStopsAtTheBudget()
    {
        // Before: 41 doublings reached gigabytes; the worker died and the executables were lost.
        QTemporaryDir dir;
        test::healthyPythonPackage(dir.path());
        writeFile(dir.path() + "/src/cpp/package.xml",
                  "<package format=\"3\"><name>cpp</name></package>\n");
        writeFile(dir.path() + "/src/cpp/CMakeLists.txt",
                  "project(cpp)\nset(x \"ab\")\nforeach(i RANGE 40)\n  set(x \"${x}${x}\")\n"
                  "endforeach()\nadd_executable(worker src/worker.cpp)\n");
        writeFile(dir.path() + "/src/cpp/src/worker.cpp",
                  "#include \"rclcpp/rclcpp.hpp\"\nclass Worker : public rclcpp::Node {\npublic:\n"
                  "  Worker() : Node(\"worker\") {}\n};\n");
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(placesOf(r, QStringLiteral("evaluation-limit")),
                 QStringList{QStringLiteral("src/cpp/CMakeLists.txt:4")});
        QStringList executables;
        for (const AtomicNode &n : r.nodes.nodes)
            executables += n.executables;
        QVERIFY2(executables.contains(QStringLiteral("worker")), qPrintable(executables.join(' ')));
    }

    void aLaunchArgumentDoubledStopsAtTheBudget_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("place");
        QTest::newRow("xml") << QStringLiteral("xml")
                             << QStringLiteral("src/pkg/launch/double.launch.xml:");
        QTest::newRow("yaml") << QStringLiteral("yaml")
                              << QStringLiteral("src/pkg/launch/double.launch.yaml:");
        QTest::newRow("py") << QStringLiteral("py")
                            << QStringLiteral("src/pkg/launch/double.launch.py:");
    }

    void aLaunchArgumentDoubledStopsAtTheBudget()
    {
        // Before: the worker died outside any one file, and nothing at all was written.
        QFETCH(QString, format);
        QFETCH(QString, place);
        QTemporaryDir dir;
        test::healthyPythonPackage(dir.path());
        writeFile(dir.path() + "/src/pkg/launch/double.launch." + format.toUtf8(),
                  doublingLaunchFile(format));
        const Recovery r = recoverWorkspace(dir.path());
        const QStringList said = placesOf(r, QStringLiteral("evaluation-limit"));
        QVERIFY2(!said.isEmpty() && said.first().startsWith(place), qPrintable(said.join(' ')));
        const NodeInstance *good = instance(r, QStringLiteral("good"));
        QVERIFY(good);
        QVERIFY(good->nameSpace.size() <= kMaxValueChars);
        bool unresolved = false;
        for (const Unresolved &u : good->unresolved)
            unresolved = unresolved || !u.kind.isEmpty();
        QVERIFY(unresolved); // the namespace is a guess, and says so
    }

    void aLongNameGetsNoQuadraticHint()
    {
        // Before: a 128 KB namespace took 156 s in the "Did you mean" edit distance. Now names
        // past 256 characters get no hint, and the distance is banded (linear in the length;
        // still used to name commands).
        QTemporaryDir dir;
        test::healthyPythonPackage(dir.path(), "listener = pkg.listener:main");
        writeFile(dir.path() + "/src/pkg/pkg/listener.py",
                  "from rclpy.node import Node\nfrom std_msgs.msg import String\n\n"
                  "class Listener(Node):\n    def __init__(self):\n"
                  "        super().__init__('listener')\n"
                  "        self.create_subscription(String, 'outt', self.cb, 10)\n");
        const QByteArray longNs(128 * 1024, 'n');
        writeFile(dir.path() + "/src/pkg/launch/long.launch.xml",
                  "<launch>\n  <node pkg=\"pkg\" exec=\"good\" name=\"good\" namespace=\"" +
                      longNs +
                      "\"/>\n  <node pkg=\"pkg\" exec=\"listener\" name=\"l\"/>\n"
                      "  <node pkg=\"pkg\" exec=\"good\" name=\"near\"/>\n</launch>\n");
        const Recovery r = recoverWorkspace(dir.path());
        QVERIFY(instance(r, QStringLiteral("good")));
        QStringList hints;
        for (const Diagnostic &d : r.architecture.diagnostics)
            if (d.message.contains(QLatin1String("Did you mean")))
                hints << d.message.left(200);
        // The short misspelling still gets its hint (one finding, at the subscription); the
        // long name none.
        QCOMPARE(hints.size(), 1);
        for (const QString &h : std::as_const(hints))
            QVERIFY2(!h.contains(QLatin1String("nnnnnnnn")), qPrintable(h));
        // Banded: far apart at the start, the distance stops at the limit at once.
        const QString a(200000, QLatin1Char('a')),
            b = QString(a).replace(0, 5, QStringLiteral("bbbbb"));
        QCOMPARE(editDistance(a, b, 3), 3);
        QCOMPARE(editDistance(QStringLiteral("scan"), QStringLiteral("scna"), 3), 2);
    }

    void includesMultiplyingIncludesStopAtTheInstanceBudget()
    {
        // Before: three 3 KB files including each other 30 x 30 times, 100 nodes each, made
        // 90,000 instances; the rosarch command died (3.2 GB) printing their warnings.
        QTemporaryDir dir;
        test::healthyPythonPackage(dir.path());
        const QStringList names = {QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")};
        for (int f = 0; f < 3; ++f) {
            QByteArray body = "<launch>\n";
            for (int i = 0; f < 2 && i < 30; ++i)
                body += QStringLiteral("  <group><push-ros-namespace namespace=\"%1%2\"/><include "
                                       "file=\"$(find-pkg-share pkg)/launch/%3.launch.xml\"/>"
                                       "</group>\n")
                            .arg(names[f])
                            .arg(i)
                            .arg(names[f + 1])
                            .toUtf8();
            for (int i = 0; i < 100; ++i)
                body += QStringLiteral("  <node pkg=\"pkg\" exec=\"good\" name=\"n%1\"/>\n")
                            .arg(i)
                            .toUtf8();
            writeFile(dir.path() + "/src/pkg/launch/" + names[f].toUtf8() + ".launch.xml",
                      body + "</launch>\n");
        }
        const Recovery r = recoverWorkspace(dir.path());
        QVERIFY(r.launch.nodes.size() + r.launch.instances.size() <= 20000);
        QVERIFY(r.launch.nodes.size() > 10000);
        const QStringList said =
            test::diagnosticsWithCode(r, QStringLiteral("launch-evaluation-limit"));
        QVERIFY2(!said.isEmpty() && said.first().contains(QLatin1String("more than 20000 nodes")),
                 qPrintable(said.join('\n')));
    }

    void manySmallLaunchFilesAreAllRead()
    {
        // Before: every read reserved the 4 MB file cap, and the read-ahead of 1,500 small
        // launch files exhausted the worker's address space.
        QTemporaryDir dir;
        test::healthyPythonPackage(dir.path());
        for (int i = 0; i < 1500; ++i)
            writeFile(dir.path() + QStringLiteral("/src/pkg/launch/l%1.launch.xml").arg(i),
                      QStringLiteral("<launch><node pkg=\"pkg\" exec=\"good\" name=\"g%1\"/>"
                                     "</launch>\n")
                          .arg(i)
                          .toUtf8());
        const Recovery r = recoverWorkspace(dir.path());
        QCOMPARE(r.launch.nodes.size(), 1500);
        QVERIFY(placesOf(r, QStringLiteral("file-too-large")).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestSizeBudgets)
#include "tst_sizebudgets.moc"
