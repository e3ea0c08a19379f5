// No control byte from a workspace reaches a terminal or an artifact, and a kill at
// any moment of a run leaves the output folder with the old result or the new, never a mix.
// Runs the real rosarch executable; the hostile workspaces are generated here.
#include "core/visibletext.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QtTest>

using rosarch::test::runRosarch;
using rosarch::test::writeFile;

namespace {

/// A Python package `pkg` with one node class, Good, started as `good`.
void healthyPackage(const QString &ws)
{
    writeFile(ws + QStringLiteral("/src/pkg/package.xml"),
              "<package format=\"3\"><name>pkg</name><export><build_type>ament_python"
              "</build_type></export></package>\n");
    writeFile(ws + QStringLiteral("/src/pkg/pkg/good.py"),
              "from rclpy.node import Node\n\nclass Good(Node):\n    def __init__(self):\n"
              "        super().__init__('good')\n");
    writeFile(ws + QStringLiteral("/src/pkg/setup.py"),
              "from setuptools import setup\nsetup(name='pkg', entry_points={'console_scripts': "
              "['good = pkg.good:main']})\n");
}

/// The first hidden control character in `text` (newline and tab allowed), or "".
QString firstControl(const QString &text)
{
    for (qsizetype i = 0; i < text.size(); ++i)
        if (rosarch::isHiddenControl(text.at(i).unicode(), rosarch::Newlines::Keep))
            return QStringLiteral("U+%1 at %2 in: %3")
                .arg(uint(text.at(i).unicode()), 4, 16, QLatin1Char('0'))
                .arg(i)
                .arg(text.mid(std::max<qsizetype>(0, i - 40), 80));
    return {};
}

/// A workspace whose file names, build file and launch files carry terminal sequences: colour,
/// bell, clear screen, set title, a C1 CSI, carriage return and newline in a file name.
void hostileWorkspace(const QString &ws)
{
    healthyPackage(ws);
    writeFile(ws + QStringLiteral("/src/pkg/launch/red\x1b[31mbell\x07.launch.xml"),
              "<launch>\n  <node pkg=\"pkg\" exec=\"good\" name=\"x\"/>\n"
              "  <include file=\"gone\x1b]0;pwned\x07.xml\"/>\n</launch>\n");
    writeFile(ws + QStringLiteral("/src/pkg/launch/new\nline\r.launch.xml"),
              "<launch>\n  <include file=\"gone.xml\"/>\n</launch>\n");
    writeFile(ws + QStringLiteral("/src/pkg/launch/csi") + QChar(0x9b) +
                  QStringLiteral("2J.launch.yaml"),
              "launch:\n- node: {pkg: pkg, exec: \"nope\\e[2J\", name: y}\n");
    writeFile(ws + QStringLiteral("/src/pkg/launch/title.launch.py"),
              "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
              "def generate_launch_description():\n    return LaunchDescription([Node(package="
              "'pkg', executable='nope\\x1b]0;title\\x07', name='t\\x7f')])\n");
    writeFile(ws + QStringLiteral("/src/cpp/package.xml"),
              "<package format=\"3\"><name>cpp</name></package>\n");
    writeFile(ws + QStringLiteral("/src/cpp/CMakeLists.txt"),
              "project(cpp)\nadd_executable(clear\x1b[2J src/worker.cpp)\n"
              "add_executable(w2 src/missing\x1b[2J.cpp)\n");
    writeFile(ws + QStringLiteral("/src/cpp/src/worker.cpp"),
              "#include \"rclcpp/rclcpp.hpp\"\nclass Worker : public rclcpp::Node {\npublic:\n"
              "  Worker() : Node(\"w\\x1b[2J\") {\n    create_publisher<std_msgs::msg::String>("
              "\"t\\a\", 10);\n  }\n};\n");
}

/// Which of two workspaces (class names beginning "NA" or "NB") the output folder holds, or
/// "mixed" when its JSON and its ACDs disagree, or an ACD is missing.
QString holds(const QString &out, int classes)
{
    const QByteArray json = rosarch::test::readFile(out + QStringLiteral("/atomic_nodes.json"));
    const QString tag = json.contains("\"NA0\"") ? QStringLiteral("A") : QStringLiteral("B");
    const QStringList acds = QDir(out + QStringLiteral("/acd")).entryList(QDir::Files);
    int ours = 0;
    for (const QString &acd : acds) {
        if (!acd.startsWith(QLatin1Char('N')))
            continue; // the healthy package's Good
        ++ours;
        if (acd.mid(1, 1) != tag)
            return QStringLiteral("mixed");
    }
    return ours == classes ? tag : QStringLiteral("mixed");
}

void manyClasses(const QString &ws, const QString &tag, int count)
{
    healthyPackage(ws);
    QByteArray body = "from rclpy.node import Node\n";
    for (int i = 0; i < count; ++i)
        body += QStringLiteral("class N%1%2(Node):\n    def __init__(self):\n"
                               "        super().__init__('n%2')\n")
                    .arg(tag)
                    .arg(i)
                    .toUtf8();
    writeFile(ws + QStringLiteral("/src/pkg/pkg/nodes.py"), body);
}

} // namespace

class TestOutputSafety : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void noControlByteReachesAnyOutput()
    {
        QTemporaryDir dir;
        const QString ws = dir.filePath(QStringLiteral("ws"));
        hostileWorkspace(ws);
        const QString out = dir.filePath(QStringLiteral("out"));
        const QList<QStringList> commands = {
            {QStringLiteral("recover"), ws, QStringLiteral("--out"), out},
            {QStringLiteral("check"), ws, QStringLiteral("--fail-on"), QStringLiteral("never")},
            {QStringLiteral("check"), ws, QStringLiteral("--format"), QStringLiteral("junit")},
            {QStringLiteral("check"), ws, QStringLiteral("--format"), QStringLiteral("sarif")},
            {QStringLiteral("check"), ws, QStringLiteral("--format"), QStringLiteral("json")},
            {QStringLiteral("suggest"), ws, QStringLiteral("--out"),
             dir.filePath(QStringLiteral("suggestions"))},
        };
        for (const QStringList &args : commands) {
            const rosarch::test::Run r = runRosarch(args);
            QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(args.join(' ') + r.err));
            QVERIFY2(firstControl(r.out).isEmpty(), qPrintable(args.first() + firstControl(r.out)));
            QVERIFY2(firstControl(r.err).isEmpty(), qPrintable(args.first() + firstControl(r.err)));
            if (args.first() != QLatin1String("recover"))
                continue;
            // One diagnostic, one line: a newline in a file name never splits it.
            int lines = 0;
            for (const QString &line : r.err.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
                QVERIFY2(line.contains(QLatin1String(": warning: ")) ||
                             line.contains(QLatin1String(": error: ")) ||
                             line.contains(QLatin1String(": info: ")),
                         qPrintable(line));
                ++lines;
            }
            QVERIFY(r.err.contains(QLatin1String("new\\x0aline\\x0d.launch.xml:2: warning:")));
            QVERIFY(r.err.contains(QLatin1String("red\\x1b[31mbell\\x07.launch.xml")));
            QVERIFY(lines >= 3);
        }
        // Every artifact: its name and its content.
        QDirIterator it(out, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
        int files = 0;
        while (it.hasNext()) {
            const QString path = it.next();
            QVERIFY2(firstControl(path).isEmpty(), qPrintable(firstControl(path)));
            const QString content = QString::fromUtf8(rosarch::test::readFile(path));
            QVERIFY2(firstControl(content).isEmpty(), qPrintable(path + firstControl(content)));
            ++files;
        }
        QVERIFY(files > 8);
    }

    void evalPrintsNoRawByteOfTheDiagramsItReads()
    {
        // Before: `rosarch eval` printed NUL, ESC and BEL from the names in the diagrams.
        QTemporaryDir dir;
        const QByteArray acd = "@startuml\ncomponent \"<<AtomicRosNodeClassifier>>\\nGood\" as "
                               "node {\n  portout \" \" as p1\n}\nframe \"p1\\nout\" as t {\n"
                               "  rectangle \"**std_msgs::msg::String**\" as r\n}\n"
                               "p1 -[#green,bold]-> t\n@enduml\n";
        writeFile(dir.filePath(QStringLiteral("ref.puml")), acd);
        QByteArray hostile = acd;
        hostile.replace("nGood", "nGo\x1b]0;t\x07od\x01");
        hostile.replace("nout", "nout\x1b[2J\x9b");
        writeFile(dir.filePath(QStringLiteral("rec.puml")), hostile);
        for (const QStringList &extra : {QStringList{}, QStringList{QStringLiteral("--json")}}) {
            const rosarch::test::Run r = runRosarch(
                QStringList{QStringLiteral("eval"), QStringLiteral("--reference"),
                            dir.filePath(QStringLiteral("ref.puml")), QStringLiteral("--recovered"),
                            dir.filePath(QStringLiteral("rec.puml"))} +
                extra);
            QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(r.err));
            QVERIFY2(firstControl(r.out).isEmpty(), qPrintable(firstControl(r.out)));
            QVERIFY2(firstControl(r.err).isEmpty(), qPrintable(firstControl(r.err)));
            // The names are there, escaped (text) or as JSON escapes.
            QVERIFY2(r.out.contains(QLatin1String("\\x1b]0;t\\x07")) ||
                         r.out.contains(QLatin1String("\\u001b]0;t\\u0007")),
                     qPrintable(r.out.left(2000)));
        }
    }

    void aKillDuringARunLeavesTheOldResultOrTheNew()
    {
        // Before: a SIGKILL while the artifacts were moved into place left the new JSON beside
        // part of the new ACDs and none of the old, and a staging folder that stayed forever.
        QTemporaryDir dir;
        constexpr int kClasses = 1500;
        const QString a = dir.filePath(QStringLiteral("a")), b = dir.filePath(QStringLiteral("b"));
        manyClasses(a, QStringLiteral("A"), kClasses);
        manyClasses(b, QStringLiteral("B"), kClasses);
        const QString out = dir.filePath(QStringLiteral("out"));
        QElapsedTimer clock;
        clock.start();
        QCOMPARE(runRosarch({QStringLiteral("recover"), a, QStringLiteral("--out"), out}).exitCode,
                 0);
        const qint64 full = std::max<qint64>(clock.elapsed(), 200);
        QCOMPARE(holds(out, kClasses), QStringLiteral("A"));
        QMap<QString, int> seen;
        for (int k = 0; k < 12; ++k) {
            const QString before = holds(out, kClasses);
            QProcess p;
            p.start(QStringLiteral(ROSARCH_BINARY),
                    {QStringLiteral("recover"), before == QLatin1String("A") ? b : a,
                     QStringLiteral("--out"), out});
            QVERIFY(p.waitForStarted());
            // Spread over the run, its end (the commit) included.
            QTest::qWait(int(full * (0.3 + 0.15 * k)));
            p.kill();
            p.waitForFinished();
            const QString after = holds(out, kClasses);
            QVERIFY2(after != QLatin1String("mixed"), qPrintable(QString::number(k)));
            ++seen[after == before ? QStringLiteral("old") : QStringLiteral("new")];
        }
        qInfo() << "after kills:" << seen;
        // The next run completes and removes what the killed ones left.
        QCOMPARE(runRosarch({QStringLiteral("recover"), b, QStringLiteral("--out"), out}).exitCode,
                 0);
        QCOMPARE(holds(out, kClasses), QStringLiteral("B"));
        QVERIFY(
            QDir(dir.path())
                .entryList({QStringLiteral(".out.rosarch-writing-*")}, QDir::Dirs | QDir::Hidden)
                .isEmpty());
        QVERIFY(QDir(out)
                    .entryList({QStringLiteral(".rosarch-writing-*")}, QDir::Dirs | QDir::Hidden)
                    .isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestOutputSafety)
#include "tst_outputsafety.moc"
