// End-to-end: the real `rosarch` executable, headless, on fixture workspaces.
#include "app/commands/commandline.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {
using rosarch::test::Run;
using rosarch::test::runRosarch;

QString exampleWorkspace()
{
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
        .filePath(QStringLiteral("resources/example_ws"));
}
} // namespace

class TestCommandLine : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void recoverWritesArtifacts()
    {
        QTemporaryDir out;
        const Run r = runRosarch(
            {QStringLiteral("recover"), exampleWorkspace(), QStringLiteral("--out"), out.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QStringLiteral("Recovered")));

        const QByteArray json =
            rosarch::test::readFile(out.filePath(QStringLiteral("atomic_nodes.json")));
        const QJsonObject root = QJsonDocument::fromJson(json).object();
        const QJsonArray packages = root.value(QStringLiteral("list_packages")).toArray();
        QCOMPARE(packages.size(), 5);
        int nodes = 0;
        QStringList classes;
        for (const auto &p : packages)
            for (const auto &n :
                 p.toObject().value(QStringLiteral("list_atomic_ros_node_classifiers")).toArray()) {
                ++nodes;
                classes << n.toObject().value(QStringLiteral("class_name")).toString();
            }
        QVERIFY2(nodes >= 7, qPrintable(classes.join(',')));
        QVERIFY(classes.contains(QStringLiteral("LidarFilter")));
        QVERIFY(classes.contains(QStringLiteral("MissionPlanner")));
        QVERIFY(!classes.contains(QStringLiteral("TaskNode")));
        QVERIFY(!classes.contains(QStringLiteral("SafetyMonitor")));

        const QDir acd(out.filePath(QStringLiteral("acd")));
        QCOMPARE(acd.entryList({QStringLiteral("*.puml")}, QDir::Files).size(), nodes);
        QVERIFY(acd.exists(QStringLiteral("LidarFilter.puml")));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("diagnostics.json"))));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("launch_dependencies.json"))));
        QVERIFY(r.out.contains(QStringLiteral("4 composites")));

        // Stage 3: one CCD per launch file and the architecture JSON.
        const QDir ccd(out.filePath(QStringLiteral("ccd")));
        QCOMPARE(ccd.entryList({QStringLiteral("*.puml")}, QDir::Files, QDir::Name),
                 (QStringList{QStringLiteral("mission.puml"), QStringLiteral("navigation.puml"),
                              QStringLiteral("robot.puml"), QStringLiteral("sensing.puml")}));
        QVERIFY(rosarch::test::readFile(ccd.filePath(QStringLiteral("robot.puml")))
                    .contains("component \":sensing\" as part1 <<RosNodePart>>"));
        const QJsonObject arch =
            QJsonDocument::fromJson(
                rosarch::test::readFile(out.filePath(QStringLiteral("architecture.json"))))
                .object();
        QVERIFY(
            !arch.value(QStringLiteral("list_composed_ros_node_classifiers")).toArray().isEmpty());
    }

    void launchArgumentsChangeTheInstances()
    {
        QTemporaryDir out;
        const Run r =
            runRosarch({QStringLiteral("recover"), exampleWorkspace(), QStringLiteral("--out"),
                        out.path(), QStringLiteral("--launch-arg"), QStringLiteral("robot_ns:=r2"),
                        QStringLiteral("--launch-arg"), QStringLiteral("use_camera:=false")});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QJsonObject root =
            QJsonDocument::fromJson(
                rosarch::test::readFile(out.filePath(QStringLiteral("launch_dependencies.json"))))
                .object();
        QCOMPARE(root.value(QStringLiteral("launch_files")).toArray().size(), 4);
        QStringList instances;
        for (const auto &n : root.value(QStringLiteral("list_atom_node_instances")).toArray()) {
            const QJsonObject o = n.toObject();
            instances << QStringLiteral("%1%2%3 %4")
                             .arg(o.value(QStringLiteral("namespace")).toString(),
                                  o.value(QStringLiteral("namespace")).toString() ==
                                          QLatin1String("/")
                                      ? QString()
                                      : QStringLiteral("/"),
                                  o.value(QStringLiteral("node_name")).toString(),
                                  o.value(QStringLiteral("active")).toBool()
                                      ? QStringLiteral("on")
                                      : QStringLiteral("off"));
        }
        QVERIFY2(instances.contains(QStringLiteral("/r2/navigator on")),
                 qPrintable(instances.join(',')));
        QVERIFY2(instances.contains(QStringLiteral("/r2/front_camera off")),
                 qPrintable(instances.join(',')));
        QVERIFY2(instances.contains(QStringLiteral("/r2/monitoring/battery_monitor on")),
                 qPrintable(instances.join(',')));

        const Run bad =
            runRosarch({QStringLiteral("recover"), exampleWorkspace(), QStringLiteral("--out"),
                        out.path(), QStringLiteral("--launch-arg"), QStringLiteral("robot_ns")});
        QCOMPARE(bad.exitCode, 2);
        QVERIFY(bad.err.contains(QStringLiteral("name:=value")));
    }

    void errorsInTheWorkspaceGiveExitCodeOne()
    {
        QTemporaryDir ws;
        QDir(ws.path()).mkpath(QStringLiteral("pkg/pkg"));
        QFile xml(ws.filePath(QStringLiteral("pkg/package.xml")));
        QVERIFY(xml.open(QIODevice::WriteOnly));
        xml.write("<package><name>pkg</name><export><build_type>ament_python</build_type></"
                  "export></package>");
        xml.close();
        QFile broken(ws.filePath(QStringLiteral("pkg/pkg/broken.py")));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write(
            "from rclpy.node import Node\n\nclass Broken(Node:\n    def __init__(self):\n");
        broken.close();
        QTemporaryDir out;
        const Run r =
            runRosarch({QStringLiteral("recover"), ws.path(), QStringLiteral("--out"), out.path()});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("pkg/pkg/broken.py:3")), qPrintable(r.err));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("atomic_nodes.json"))));
    }

    void usageErrorsGiveExitCodeTwo()
    {
        QCOMPARE(runRosarch({QStringLiteral("recover")}).exitCode, 2);
        QCOMPARE(runRosarch({QStringLiteral("recover"), exampleWorkspace()}).exitCode, 2);
        const Run missing = runRosarch({QStringLiteral("recover"), QStringLiteral("/no/such/ws"),
                                        QStringLiteral("--out"), QStringLiteral("/tmp/x")});
        QCOMPARE(missing.exitCode, 2);
        QVERIFY(missing.err.contains(QStringLiteral("Not a folder")));
        const Run unknown =
            runRosarch({QStringLiteral("recover"), exampleWorkspace(), QStringLiteral("--bogus")});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY(unknown.err.contains(QStringLiteral("bogus")));
    }

    void aMistypedCommandNeverOpensTheGui()
    {
        // No display here (runRosarch removes DISPLAY and QT_QPA_PLATFORM): a window would abort
        // in Qt's platform plugin. A mistyped command gets a hint, a wrong path a message.
        const Run typo = runRosarch({QStringLiteral("recovr"), exampleWorkspace()});
        QCOMPARE(typo.exitCode, 2);
        QVERIFY2(typo.err.contains(QStringLiteral("Unknown command: recovr")),
                 qPrintable(typo.err));
        QVERIFY2(typo.err.contains(QStringLiteral("Did you mean: rosarch recover?")),
                 qPrintable(typo.err));
        const Run far = runRosarch({QStringLiteral("checkx")});
        QCOMPARE(far.exitCode, 2);
        QVERIFY2(far.err.contains(QStringLiteral("Unknown command: checkx")), qPrintable(far.err));
        QVERIFY(!far.err.contains(QStringLiteral("platform plugin")));
        const Run path = runRosarch({QStringLiteral("/no/such/workspace")});
        QCOMPARE(path.exitCode, 2);
        QVERIFY2(path.err.contains(QStringLiteral("Not a folder: /no/such/workspace")),
                 qPrintable(path.err));
        QCOMPARE(rosarch::CommandLine::nearestCommand(QStringLiteral("sugest")),
                 QStringLiteral("suggest"));
        QCOMPARE(rosarch::CommandLine::nearestCommand(QStringLiteral("ev")),
                 QStringLiteral("eval"));
        QCOMPARE(rosarch::CommandLine::nearestCommand(QStringLiteral("xyzzy")), QString());
    }

    void helpAndVersion()
    {
        const Run help = runRosarch({QStringLiteral("--help")});
        QCOMPARE(help.exitCode, 0);
        QVERIFY(help.out.contains(QStringLiteral("rosarch recover <workspace> --out <dir>")));
        const Run version = runRosarch({QStringLiteral("--version")});
        QCOMPARE(version.exitCode, 0);
        QCOMPARE(version.out.trimmed(), QStringLiteral("rosarch " ROSARCH_VERSION));
    }

    void renderWithPlantUml()
    {
        // The same pictures the published pipeline gets: every ACD and CCD rendered by the real
        // PlantUML, next to its .puml; plus the Mermaid and DOT exports.
        QTemporaryDir out;
        QTemporaryDir copy;
        const QString ws = copy.filePath(QStringLiteral("ws"));
        rosarch::test::copyTree(rosarch::test::dataDir(QStringLiteral("compose_system/ws")), ws);
        const QString jar = QStringLiteral(ROSARCH_PLANTUML_JAR);
        Run r = runRosarch({QStringLiteral("recover"), ws, QStringLiteral("--out"), out.path(),
                            QStringLiteral("--render"), QStringLiteral("svg"),
                            QStringLiteral("--plantuml-jar"), jar});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY(r.out.contains(QLatin1String("Rendered 7 diagrams as svg with PlantUML.")));
        QStringList pumls;
        for (const QString &sub : {QStringLiteral("acd"), QStringLiteral("ccd")})
            for (const QString &f :
                 QDir(out.filePath(sub)).entryList({QStringLiteral("*.puml")}, QDir::Files))
                pumls << out.filePath(sub + QLatin1Char('/') + f);
        QCOMPARE(pumls.size(), 7);
        for (const QString &puml : std::as_const(pumls)) {
            const QString svg = puml.left(puml.size() - 4) + QStringLiteral("svg");
            QVERIFY2(rosarch::test::readFile(svg).contains("<svg"), qPrintable(svg));
        }
        QVERIFY(rosarch::test::readFile(out.filePath(QStringLiteral("ccd/system.svg")))
                    .contains("backup_planner"));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("mermaid/system.md"))));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("mermaid/vision.md"))));
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("graph/system.dot"))));
        // A later run with the same result writes nothing: the pictures are still those of
        // the diagrams. Once the result changes, no stale picture is left behind.
        r = runRosarch({QStringLiteral("recover"), ws, QStringLiteral("--out"), out.path()});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("ccd/system.svg"))));
        QDirIterator python(ws, {QStringLiteral("*.py")}, QDir::Files,
                            QDirIterator::Subdirectories);
        QVERIFY(python.hasNext());
        const QString added = QFileInfo(python.next()).path() + QStringLiteral("/added_node.py");
        rosarch::test::writeFile(added,
                                 "from rclpy.node import Node\n\nclass Added(Node):\n"
                                 "    def __init__(self):\n        super().__init__('added')\n");
        r = runRosarch({QStringLiteral("recover"), ws, QStringLiteral("--out"), out.path()});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(QFile::exists(out.filePath(QStringLiteral("acd/Added.puml"))));
        QVERIFY(!QFile::exists(out.filePath(QStringLiteral("ccd/system.svg"))));
        // A jar that is not there is said before anything runs, and no other jar is used.
        r = runRosarch({QStringLiteral("recover"), ws, QStringLiteral("--out"), out.path(),
                        QStringLiteral("--render"), QStringLiteral("png"),
                        QStringLiteral("--plantuml-jar"), QStringLiteral("/no/plantuml.jar")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QLatin1String("No PlantUML jar found")));
        r = runRosarch({QStringLiteral("recover"), ws, QStringLiteral("--out"), out.path(),
                        QStringLiteral("--render"), QStringLiteral("pdf")});
        QCOMPARE(r.exitCode, 2);
    }

    void aFailedWriteLeavesThePreviousArtifacts()
    {
        // A disk that fills up half-way (here: a 2 KB file-size limit, so the larger files
        // fail to write) leaves the previous run's artifacts as they were, and no staging
        // folder behind. Before, 11 of 16 files were half-written.
        QTemporaryDir out;
        const QString ws = rosarch::test::dataDir(QStringLiteral("compose_system/ws"));
        QCOMPARE(runRosarch({QStringLiteral("recover"), ws, QStringLiteral("--out"), out.path()})
                     .exitCode,
                 0);
        QMap<QString, QByteArray> before;
        QDirIterator it(out.path(), QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            const QString f = it.next();
            before.insert(f, rosarch::test::readFile(f));
        }
        QVERIFY(before.size() > 10);
        QProcess sh;
        sh.setProcessChannelMode(QProcess::MergedChannels);
        sh.start(QStringLiteral("sh"),
                 {QStringLiteral("-c"),
                  QStringLiteral("trap '' XFSZ; ulimit -f 4; exec \"$0\" recover \"$1\" --out "
                                 "\"$2\" --launch-arg unused:=1"),
                  QStringLiteral(ROSARCH_BINARY), exampleWorkspace(), out.path()});
        QVERIFY(sh.waitForFinished(60000));
        const QString output = QString::fromUtf8(sh.readAll());
        QVERIFY2(sh.exitCode() == 1 && output.contains(QLatin1String("Cannot write")),
                 qPrintable(output));
        QMap<QString, QByteArray> after;
        QDirIterator again(out.path(), QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
        while (again.hasNext()) {
            const QString f = again.next();
            after.insert(f, rosarch::test::readFile(f));
        }
        QCOMPARE(after.keys(), before.keys());
        QVERIFY(after == before);
        QVERIFY(QDir(out.path())
                    .entryList({QStringLiteral(".rosarch-writing-*")}, QDir::Dirs | QDir::Hidden)
                    .isEmpty());
        QVERIFY(
            QDir(QFileInfo(out.path()).path())
                .entryList(
                    {QStringLiteral(".%1.rosarch-writing-*").arg(QFileInfo(out.path()).fileName())},
                    QDir::Dirs | QDir::Hidden)
                .isEmpty());
    }

    void unwritableOutputIsReported()
    {
        QTemporaryDir dir;
        QFile blocker(dir.filePath(QStringLiteral("file")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        const Run r =
            runRosarch({QStringLiteral("recover"), exampleWorkspace(), QStringLiteral("--out"),
                        dir.filePath(QStringLiteral("file/out"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.err.contains(QStringLiteral("Cannot create")));
    }
};

QTEST_GUILESS_MAIN(TestCommandLine)
#include "tst_commandline.moc"
