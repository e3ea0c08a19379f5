// Interface models (blueprint §1): the data files under interfaces/ load and validate against
// their schemas with a real JSON-schema validator, and a workspace whose launch file starts
// code outside it (tests/data/interface_models: a simulator's spawn file, robot_state_publisher,
// rviz2) is wired through the models' ports, which are marked as modelled and never findings.
#include "interfaces/interfacemodel.h"
#include "interfaces/observability.h"
#include "pipeline/recovery.h"
#include "support/jsonschemacheck.h"
#include "support/testsupport.h"

#include <QDir>
#include <QProcess>
#include <QtTest>

using namespace rosarch;

namespace {

} // namespace

class TestInterfaceModels : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void everyModelLoadsAndValidates()
    {
        const QDir dir(test::sourceFile(QStringLiteral("interfaces/models")));
        QStringList files;
        for (const QString &f : dir.entryList({QStringLiteral("*.json")}, QDir::Files))
            files << dir.filePath(f);
        QVERIFY(files.size() >= 7);
        QString output;
        QCOMPARE(test::validateJsonSchema(
                     test::sourceFile(QStringLiteral("schemas/interface-model.schema.json")), files,
                     &output),
                 0);
        // The same files, as the tool reads them (from its resources), without a problem.
        QStringList problems;
        const InterfaceModels fromSource = InterfaceModels::fromFolder(dir.path(), &problems);
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
        QCOMPARE(fromSource.all().size(), files.size());
        QCOMPARE(InterfaceModels::builtIn().all(), fromSource.all());
        // The validator is not a yes-man: a port without a type is refused by both.
        QTemporaryDir tmp;
        QFile bad(tmp.filePath(QStringLiteral("bad.json")));
        QVERIFY(bad.open(QIODevice::WriteOnly));
        bad.write(R"({"name": "x", "package": "x", "executables": ["x"],
                      "ports": [{"kind": "publisher", "name": "out"}]})");
        bad.close();
        QCOMPARE(test::validateJsonSchema(
                     test::sourceFile(QStringLiteral("schemas/interface-model.schema.json")),
                     {bad.fileName()}, &output),
                 1);
        InterfaceModels::fromFolder(tmp.path(), &problems);
        QCOMPARE(problems, (QStringList{QStringLiteral(
                               "bad.json: x: a port needs a known kind, a name and a type "
                               "pkg/msg/T")}));
    }

    void observabilityRulesValidateAndRecognise()
    {
        QString output;
        QCOMPARE(test::validateJsonSchema(
                     test::sourceFile(QStringLiteral("schemas/observability.schema.json")),
                     {test::sourceFile(QStringLiteral("interfaces/observability.json"))}, &output),
                 0);
        const Observability &o = Observability::builtIn();
        QVERIFY(!o.isEmpty());
        QVERIFY(o.covers(QStringLiteral("/planning/debug/path"),
                         QStringLiteral("nav_msgs/msg/Path"), {}));
        QVERIFY(o.covers(QStringLiteral("/lidar/processing_time_ms"),
                         QStringLiteral("std_msgs/msg/Float64"), {}));
        QVERIFY(o.covers(QStringLiteral("/outline"),
                         QStringLiteral("visualization_msgs/msg/Marker"), {}));
        QVERIFY(o.covers(QStringLiteral("/x"), QStringLiteral("std_msgs/msg/String"),
                         QStringLiteral("autoware_utils::DebugPublisher")));
        // "debug" only as a whole segment or its prefix: debugger_state is not an output.
        QVERIFY(!o.covers(QStringLiteral("/debugger_state"), QStringLiteral("std_msgs/msg/String"),
                          {}));
        QVERIFY(
            !o.covers(QStringLiteral("/scan"), QStringLiteral("sensor_msgs/msg/LaserScan"), {}));
        QStringList problems;
        const Observability own = Observability::fromJson(
            QJsonObject{{QStringLiteral("name_segments"),
                         QJsonArray{QStringLiteral("^trace$"), QStringLiteral("(")}}},
            &problems);
        QCOMPARE(problems.size(), 1);
        QVERIFY(own.covers(QStringLiteral("/a/trace"), QString(), {}));
    }

    void lookupsByExecutableAndLaunchFile()
    {
        const InterfaceModels &m = InterfaceModels::builtIn();
        QCOMPARE(m.executable(QStringLiteral("joint_state_publisher_gui"),
                              QStringLiteral("joint_state_publisher_gui"))
                     ->name,
                 QStringLiteral("joint_state_publisher"));
        QVERIFY(!m.executable(QStringLiteral("rviz2"), QStringLiteral("other")));
        QCOMPARE(m.launchFile(QStringLiteral("nav2_minimal_tb3_sim"),
                              QStringLiteral("/launch/spawn_tb3.launch.py"))
                     ->namespaceArgument,
                 QStringLiteral("namespace"));
        const QList<Port> ports =
            m.executable(QStringLiteral("tf2_ros"), QStringLiteral("static_transform_publisher"))
                ->portsAt(Evidence{QStringLiteral("a.launch.py"), 3, 1, 3, 9});
        QCOMPARE(ports.size(), 1);
        QCOMPARE(ports.first().id, QStringLiteral("m1"));
        QCOMPARE(ports.first().name, QStringLiteral("/tf_static"));
        QCOMPARE(ports.first().via, QStringLiteral("interface model static_transform_publisher"));
        QCOMPARE(ports.first().evidence.line, 3);
    }

    void anRvizConfigurationGivesTheDisplayedTopics()
    {
        const InterfaceModel *rviz =
            InterfaceModels::builtIn().executable(QStringLiteral("rviz2"), QStringLiteral("rviz2"));
        QVERIFY(rviz);
        QCOMPARE(rviz->configArgument, QStringLiteral("-d"));
        const QByteArray config = R"(Visualization Manager:
  Displays:
    - Class: rviz_default_plugins/Path
      Name: Plan
      Topic:
        Depth: 5
        Value: plan
    - Class: rviz_default_plugins/Map
      Topic:
        Value: "/map"
      Update Topic:
        Value: /map_updates
    - Class: rviz_default_plugins/Grid
      Name: Grid
  Tools:
    - Class: rviz_default_plugins/SetInitialPose
      Topic:
        Value: /initialpose
broken: [
)";
        QStringList ports;
        for (const Port &p : rviz->portsFromConfig(config, QStringLiteral("a.rviz"), 7))
            ports << QStringLiteral("%1 %2 %3 %4 line %5")
                         .arg(p.id, portKindName(p.kind), p.name, p.type)
                         .arg(p.evidence.line);
        QCOMPARE(
            ports,
            (QStringList{QStringLiteral("m7 subscriber plan nav_msgs/msg/Path line 7"),
                         QStringLiteral("m8 subscriber /map nav_msgs/msg/OccupancyGrid line 10"),
                         // the updates of a map are not the map: their type is not guessed
                         QStringLiteral("m9 subscriber /map_updates  line 12"),
                         QStringLiteral("m10 publisher /initialpose "
                                        "geometry_msgs/msg/PoseWithCovarianceStamped line 18")}));
        // A configuration with more topics than the bound gives the first kMaxConfigPorts.
        QByteArray huge("Visualization Manager:\n  Displays:\n");
        for (int i = 0; i < 1200; ++i)
            huge += "    - Class: rviz_default_plugins/Path\n      Topic:\n        Value: /t" +
                    QByteArray::number(i) + '\n';
        QCOMPARE(rviz->portsFromConfig(huge, QStringLiteral("a.rviz"), 1).size(),
                 InterfaceModel::kMaxConfigPorts);
        // Another format, or a model without one, reads nothing.
        QVERIFY(InterfaceModels::builtIn()
                    .executable(QStringLiteral("joy"), QStringLiteral("joy_node"))
                    ->portsFromConfig(config, QStringLiteral("a.rviz"), 1)
                    .isEmpty());
    }

    void aWorkspaceIsWiredThroughTheModels()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("interface_models/ws")));
        const Composite *sim = nullptr;
        for (const Composite &c : r.architecture.composites)
            if (c.parentId.isEmpty())
                sim = &c;
        QVERIFY(sim);
        QStringList channels;
        for (const Channel &ch : sim->channels)
            channels << ch.name;
        channels.sort();
        QCOMPARE(
            channels,
            (QStringList{QStringLiteral("/robot1/cmd_vel"), QStringLiteral("/robot1/joint_states"),
                         QStringLiteral("/robot1/odom"), QStringLiteral("/robot1/scan"),
                         QStringLiteral("/tf"), QStringLiteral("/tf_static")}));
        QStringList modelled;
        for (const RosNodePart &part : sim->parts)
            for (const PartPort &p : part.ports)
                if (!p.model.isEmpty())
                    modelled
                        << QStringLiteral("%1 %2 %3").arg(p.model, portKindName(p.kind), p.name);
        // the simulator's 7, robot_state_publisher's 4, rviz2's 5 and the 4 its configuration
        // displays (its goal tool is the model's own /goal_pose, not a second one)
        QCOMPARE(modelled.size(), 20);
        QVERIFY(
            modelled.contains(QStringLiteral("nav2_minimal_tb3_sim subscriber /robot1/cmd_vel")));
        QVERIFY(modelled.contains(QStringLiteral("rviz2 publisher /goal_pose")));
        QVERIFY(modelled.contains(QStringLiteral("rviz2 subscriber /robot1/scan")));
        QVERIFY(modelled.contains(QStringLiteral("rviz2 subscriber /vendor/status")));
        QCOMPARE(modelled.filter(QStringLiteral("/goal_pose")).size(), 1);
        // The configuration file is named as the instance's, for the analysis cache to watch.
        QStringList configs;
        for (const NodeInstance &n : r.launch.nodes)
            if (!n.modelConfig.isEmpty())
                configs << n.interfaceModel + QLatin1Char(' ') + n.modelConfig;
        QCOMPARE(configs, QStringList{QStringLiteral("rviz2 src/sim_bringup/rviz/sim.rviz")});
        // The models' open ports (robot_description, /initialpose, /clock, ...) are no findings;
        // the robot's goal under its namespace, which RViz at the root does not feed, is: the
        // same name at the root, open too, is the evidence.
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 %2:%3 | %4")
                         .arg(d.code, d.evidence.file)
                         .arg(d.evidence.line)
                         .arg(d.message);
        QCOMPARE(found, (QStringList{QStringLiteral(
                            "topic-unpublished src/sim_bringup/sim_bringup/follower.py:16 | "
                            "/robot1/follower subscribes to /robot1/goal_pose, which no node "
                            "started alongside it publishes. Did you mean /goal_pose?")}));
        QStringList external;
        for (const Diagnostic &d : r.launch.diagnostics)
            if (d.code == QLatin1String("external-include"))
                external << d.message;
        QCOMPARE(external, (QStringList{QStringLiteral(
                               "Include of spawn_tb3.launch.py from package nav2_minimal_tb3_sim, "
                               "which is not in the workspace. The interface model "
                               "nav2_minimal_tb3_sim gives the ports of its nodes.")}));
    }
};

QTEST_GUILESS_MAIN(TestInterfaceModels)
#include "tst_interfacemodels.moc"
