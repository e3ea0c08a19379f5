// The architecture checks ROSDiscover's users rely on, on tests/data/check_system: a misspelt
// topic gets the nearest existing name as a hint, two nodes share a name, a remap sends a
// subscription to a topic nobody publishes, and literal QoS that cannot match (Python against
// Python, Python against C++); plus the QoS reading itself and the findings' stable keys.
#include "qos.h"
#include "recovery.h"
#include "testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QList<Diagnostic> ofCode(const QList<Diagnostic> &all, const QString &code)
{
    QList<Diagnostic> out;
    for (const Diagnostic &d : all)
        if (d.code == code)
            out << d;
    return out;
}

QString at(const Evidence &e)
{
    return QStringLiteral("%1:%2").arg(e.file).arg(e.line);
}

} // namespace

class TestArchitectureChecks : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        m_recovery = recoverWorkspace(test::dataDir(QStringLiteral("check_system/ws")));
        m_diagnostics = m_recovery.architecture.diagnostics;
    }

    void qosIsReadAtTheCall()
    {
        QStringList qos;
        for (const AtomicNode &n : std::as_const(m_recovery.nodes.nodes))
            for (const Port &p : n.ports)
                qos << QStringLiteral("%1 %2: %3").arg(n.className, p.name, p.qos);
        qos.sort();
        QCOMPARE(qos, (QStringList{QStringLiteral(
                                       "Base cmd_vel: rclcpp::QoS(rclcpp::KeepLast(1)).reliable()"),
                                   // the callback before the QoS is skipped
                                   QStringLiteral("Base map: rclcpp::QoS(1).transient_local()"),
                                   QStringLiteral("Lidar scan: qos_profile_sensor_data"),
                                   QStringLiteral("Lidar wheel_odom: 10"),
                                   QStringLiteral("Mapper initialpose: 10"),
                                   QStringLiteral("Mapper map: latched"),
                                   QStringLiteral("Mapper scan: QoSProfile(depth=5, "
                                                  "reliability=ReliabilityPolicy.RELIABLE)"),
                                   QStringLiteral("Mapper whel_odom: 10"),
                                   QStringLiteral("Teleop cmd_vel: QoSProfile(depth=1, "
                                                  "reliability=ReliabilityPolicy.BEST_EFFORT)"),
                                   QStringLiteral("Viewer map: 1"),
                                   QStringLiteral("Viewer scan: qos_profile_sensor_data")}));
    }

    void findsExactlyWhatTheFixtureHolds()
    {
        QStringList codes;
        for (const Diagnostic &d : std::as_const(m_diagnostics))
            codes << d.code;
        codes.sort();
        QCOMPARE(
            codes,
            (QStringList{QStringLiteral("duplicate-node-name"), QStringLiteral("qos-incompatible"),
                         QStringLiteral("qos-incompatible"), QStringLiteral("remap-target-unused"),
                         QStringLiteral("topic-unheard"), QStringLiteral("topic-unpublished")}));
    }

    void danglingTopicNamesTheNearestOne()
    {
        const QList<Diagnostic> d = ofCode(m_diagnostics, QStringLiteral("topic-unpublished"));
        QCOMPARE(d.size(), 1);
        QVERIFY2(d[0].message.endsWith(QLatin1String("Did you mean /wheel_odom?")),
                 qPrintable(d[0].message));
        QCOMPARE(at(d[0].evidence), QStringLiteral("src/patrol/patrol/mapper.py:20"));
        QCOMPARE(d[0].related.size(), 1);
        QCOMPARE(at(d[0].related[0].evidence), QStringLiteral("src/patrol/patrol/lidar.py:15"));
        // And the other way round: the unheard publisher names the misspelt subscription.
        const QList<Diagnostic> u = ofCode(m_diagnostics, QStringLiteral("topic-unheard"));
        QCOMPARE(u.size(), 1);
        QVERIFY(u[0].message.endsWith(QLatin1String("Did you mean /whel_odom?")));
    }

    void noHintWhenNothingIsClose()
    {
        // /initial_pose is far from every published name: the finding has no hint.
        const QList<Diagnostic> d = ofCode(m_diagnostics, QStringLiteral("remap-target-unused"));
        QCOMPARE(d.size(), 1);
        QVERIFY(!d[0].message.contains(QLatin1String("Did you mean")));
    }

    void duplicateNodeNames()
    {
        const QList<Diagnostic> d = ofCode(m_diagnostics, QStringLiteral("duplicate-node-name"));
        QCOMPARE(d.size(), 1);
        QVERIFY(d[0].message.startsWith(QLatin1String("2 nodes are named /viewer")));
        QCOMPARE(at(d[0].evidence), QStringLiteral("src/patrol/launch/patrol.launch.py:10"));
        QCOMPARE(d[0].related.size(), 1);
        QCOMPARE(at(d[0].related[0].evidence),
                 QStringLiteral("src/patrol/launch/patrol.launch.py:11"));
    }

    void remapWhoseTargetNobodyPublishes()
    {
        const Diagnostic d = ofCode(m_diagnostics, QStringLiteral("remap-target-unused")).value(0);
        QCOMPARE(d.severity, Diagnostic::Severity::Warning); // an input nobody feeds
        QVERIFY2(d.message.contains(QLatin1String("initialpose to /initial_pose")),
                 qPrintable(d.message));
        // The rule is written in the launch file; the port's creation is the related place.
        QCOMPARE(at(d.evidence), QStringLiteral("src/patrol/launch/patrol.launch.py:8"));
        QCOMPARE(at(d.related.value(0).evidence), QStringLiteral("src/patrol/patrol/mapper.py:21"));
    }

    void incompatibleLiteralQos()
    {
        const QList<Diagnostic> d = ofCode(m_diagnostics, QStringLiteral("qos-incompatible"));
        QStringList pairs;
        for (const Diagnostic &x : d) {
            QVERIFY(x.message.contains(QLatin1String("best-effort publisher and a reliable")));
            pairs << at(x.evidence) + QStringLiteral(" <- ") + at(x.related.value(0).evidence);
        }
        pairs.sort();
        // Python subscription against a Python publisher, and C++ against Python. The viewer's
        // sensor-data scan and its volatile map subscription are compatible: not reported.
        QCOMPARE(pairs, (QStringList{QStringLiteral("src/drive/src/base.cpp:17 <- "
                                                    "src/patrol/patrol/teleop.py:13"),
                                     QStringLiteral("src/patrol/patrol/mapper.py:16 <- "
                                                    "src/patrol/patrol/lidar.py:14")}));
    }

    void qosAsWritten_data()
    {
        QTest::addColumn<QString>("written");
        QTest::addColumn<QString>("reliability");
        QTest::addColumn<QString>("durability");
        const QString R = QStringLiteral("reliable"), B = QStringLiteral("best_effort"),
                      V = QStringLiteral("volatile"), T = QStringLiteral("transient_local"), U;
        QTest::newRow("depth") << QStringLiteral("10") << R << V;
        QTest::newRow("cpp QoS") << QStringLiteral("rclcpp::QoS(10)") << R << V;
        QTest::newRow("cpp best effort")
            << QStringLiteral("rclcpp::QoS(rclcpp::KeepLast(5)).best_effort()") << B << V;
        QTest::newRow("cpp sensor data") << QStringLiteral("rclcpp::SensorDataQoS()") << B << V;
        QTest::newRow("cpp latched")
            << QStringLiteral("rclcpp::QoS(1).transient_local().reliable()") << R << T;
        QTest::newRow("cpp rmw enum")
            << QStringLiteral("rclcpp::QoS(1).reliability(RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT)")
            << B << V;
        QTest::newRow("cpp system default")
            << QStringLiteral("rclcpp::SystemDefaultsQoS()") << U << U;
        QTest::newRow("py sensor data") << QStringLiteral("qos_profile_sensor_data") << B << V;
        QTest::newRow("py profile")
            << QStringLiteral("QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)")
            << R << T;
        QTest::newRow("py old enum")
            << QStringLiteral("QoSProfile(depth=1, "
                              "reliability=QoSReliabilityPolicy.BEST_EFFORT)")
            << B << V;
        // Variables decide nothing: the check needs both sides literal.
        QTest::newRow("variable") << QStringLiteral("qos") << U << U;
        QTest::newRow("member") << QStringLiteral("qos_profile_") << U << U;
        QTest::newRow("parameter depth") << QStringLiteral("rclcpp::QoS(depth_)") << U << U;
        // An explicit policy on a profile that is otherwise a variable still counts...
        QTest::newRow("explicit on variable")
            << QStringLiteral("rclcpp::QoS(depth_).best_effort()") << B << U;
        // ...but a project's own named profile (navigation2's) is not taken at its name.
        QTest::newRow("project profile") << QStringLiteral("nav2::qos::SensorDataQoS()") << U << U;
        QTest::newRow("a callback named reliably")
            << QStringLiteral("std::bind(&N::onReliableData, this, _1)") << U << U;
        QTest::newRow("none") << QString() << U << U;
    }

    void qosAsWritten()
    {
        QFETCH(QString, written);
        QFETCH(QString, reliability);
        QFETCH(QString, durability);
        const QosProfile q = QosProfile::fromWritten(written);
        QCOMPARE(QosProfile::reliabilityName(q.reliability), reliability);
        QCOMPARE(QosProfile::durabilityName(q.durability), durability);
    }

    void qosRules()
    {
        const QosProfile be = QosProfile::fromWritten(QStringLiteral("qos_profile_sensor_data"));
        const QosProfile rel = QosProfile::fromWritten(QStringLiteral("10"));
        const QosProfile latched =
            QosProfile::fromWritten(QStringLiteral("rclcpp::QoS(1).transient_local()"));
        const QosProfile unknown = QosProfile::fromWritten(QStringLiteral("qos"));
        QVERIFY(!QosProfile::incompatibility(be, rel).isEmpty());
        QVERIFY(QosProfile::incompatibility(rel, be).isEmpty()); // more is offered: fine
        QVERIFY(!QosProfile::incompatibility(rel, latched).isEmpty());
        QVERIFY(QosProfile::incompatibility(latched, rel).isEmpty());
        QVERIFY(QosProfile::incompatibility(unknown, rel).isEmpty());
        QVERIFY(QosProfile::incompatibility(be, unknown).isEmpty());
    }

    void keysIgnoreLinesButNotWhat()
    {
        const Diagnostic d = m_diagnostics.value(0);
        Diagnostic moved = d;
        moved.evidence.line += 7;
        moved.evidence.column = 1;
        QCOMPARE(moved.key(), d.key());
        QVERIFY(d.key().startsWith(d.code + QLatin1Char(':')));
        Diagnostic other = d;
        other.message += QLatin1Char('!');
        QVERIFY(other.key() != d.key());
        QSet<QString> keys;
        for (const Diagnostic &x : std::as_const(m_diagnostics))
            keys.insert(x.key());
        QCOMPARE(keys.size(), m_diagnostics.size());
    }

    void oneFindingPerSystemWithItsContexts()
    {
        // rover's planner is started by sim and field (both with the odometry) and, under the
        // namespace robot1, by fleet: its unpublished /map is one finding seen in two systems
        // (the same node, the same name), and another one in the third (another name).
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("check_roots/ws")));
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 | %2 | %3")
                         .arg(d.code, d.message, d.contexts.join(QLatin1Char(',')));
        found.sort();
        const QString launch = QStringLiteral("src/rover/launch/");
        QCOMPARE(
            found,
            (QStringList{
                QStringLiteral("topic-unheard | /odometry publishes /odom_raw, which no node "
                               "started alongside it subscribes to. | %1field.launch.py,%1sim."
                               "launch.py")
                    .arg(launch),
                QStringLiteral("topic-unpublished | /planner subscribes to /map, which no "
                               "node started alongside it publishes. | %1field.launch.py,%1sim."
                               "launch.py")
                    .arg(launch),
                QStringLiteral("topic-unpublished | /robot1/planner subscribes to /robot1/map, "
                               "which no node started alongside it publishes. | "
                               "%1fleet.launch.py")
                    .arg(launch),
                QStringLiteral("topic-unpublished | /robot1/planner subscribes to "
                               "/robot1/odom, which no node started alongside it publishes. "
                               "| %1fleet.launch.py")
                    .arg(launch)}));
        // Each system's own wording stays an alias key: baselines written before still match.
        for (const Diagnostic &d : r.architecture.diagnostics) {
            QCOMPARE(d.aliases.size(), d.contexts.size());
            for (qsizetype i = 0; i < d.contexts.size(); ++i) {
                Diagnostic old = d;
                old.message.replace(QStringLiteral("started alongside it"),
                                    QStringLiteral("started by ") + d.contexts.at(i));
                QCOMPARE(d.aliases.at(i), old.key());
                QVERIFY(old.key() != d.key());
                QVERIFY(d.isIn(QSet<QString>{old.key()}));
            }
        }
    }

    void childNodesTakePartAndViewedTopicsAreNoFindings()
    {
        // cpp_child_nodes: two servers each create a grid-map node inside themselves; a
        // watcher reads both grids, and an RViz configuration displays one grid's outline.
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("cpp_child_nodes/ws")));
        QStringList children;
        for (const NodeInstance &n : r.launch.nodes)
            if (!n.parentNode.isEmpty())
                children << QStringLiteral("%1 %2 in %3, child of %4")
                                .arg(n.id, n.nodeName, n.nameSpace, n.parentNode);
        QCOMPARE(children,
                 (QStringList{QStringLiteral("n2 world_grid in /rover/world_grid, child of n1"),
                              QStringLiteral("n4 near_grid in /rover/near_grid, child of n3")}));
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 %2:%3 | %4")
                         .arg(d.code, d.evidence.file)
                         .arg(d.evidence.line)
                         .arg(d.message);
        found.sort();
        QCOMPARE(
            found,
            (QStringList{
                QStringLiteral("topic-unheard src/yard_grid/src/grid_map_node.cpp:42 | "
                               "/rover/near_grid/near_grid publishes /rover/near_grid/outline, "
                               "which no node started alongside it subscribes to."),
                QStringLiteral("topic-unpublished src/yard_grid/src/scan_layer.cpp:15 | "
                               "/rover/world_grid/world_grid subscribes to /scan, which no "
                               "node started alongside it publishes.")}));
        QCOMPARE(r.launch.viewedTopics.size(), qsizetype(2));
        QStringList externals;
        for (const Diagnostic &d : r.architecture.diagnostics)
            externals << d.external;
        externals.sort();
        QCOMPARE(externals, (QStringList{QStringLiteral("input /scan"),
                                         QStringLiteral("output /rover/near_grid/outline")}));
    }

    void namesAnEntryPointTakesAsArgumentsAreItsInterface()
    {
        // launch_root_wiring: avoidance.launch.xml remaps the avoider's input to an argument
        // whose default is /front/range; robot.launch.py wires everything it starts.
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("launch_root_wiring/ws")));
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 %2 | %3")
                         .arg(d.code, d.message, d.contexts.join(QLatin1Char(',')));
        QCOMPARE(found, QStringList{QStringLiteral(
                            "topic-unheard /range_sim publishes /sim/range, which no node "
                            "started alongside it subscribes to. | "
                            "src/pad_robot/launch/avoidance.launch.xml")});
    }

    void rvizConfigurationsAreReadWithinBounds()
    {
        // A configuration naming 3,000 topics gives the first 1,000 and says so; a binary one
        // is skipped with a diagnostic, like any binary file.
        QTemporaryDir dir;
        const QString root = dir.path();
        test::writeFile(root + "/src/p/package.xml",
                        "<package format=\"3\"><name>p</name><export><build_type>ament_cmake"
                        "</build_type></export></package>");
        QByteArray big = "Visualization Manager:\n  Displays:\n";
        for (int i = 0; i < 3000; ++i)
            big += "    - Class: rviz_default_plugins/Map\n      Topic:\n        Value: /t" +
                   QByteArray::number(i) + "\n";
        test::writeFile(root + "/src/p/rviz/big.rviz", big);
        test::writeFile(root + "/src/p/rviz/bin.rviz", QByteArray("Panels:\0\x01\xff", 11));
        const Recovery r = recoverWorkspace(root);
        QCOMPARE(r.launch.viewedTopics.size(), qsizetype(1000));
        QStringList codes;
        for (const Diagnostic &d : r.nodes.diagnostics + r.launch.diagnostics)
            codes << d.code + QLatin1Char(' ') + d.evidence.file;
        QVERIFY2(codes.contains(QStringLiteral("launch-evaluation-limit src/p/rviz/big.rviz")),
                 qPrintable(codes.join(u',')));
        QVERIFY2(codes.contains(QStringLiteral("binary-file src/p/rviz/bin.rviz")),
                 qPrintable(codes.join(u',')));
    }

    void expectedExternalsAreNoFindings()
    {
        // The two findings of cpp_child_nodes, declared as expected externals: one by its
        // name, one by a pattern; a declaration of the other direction accepts nothing.
        const QString ws = test::dataDir(QStringLiteral("cpp_child_nodes/ws"));
        LaunchOptions options;
        options.externals = {{QStringLiteral("/scan"), true, QString()}};
        QCOMPARE(recoverWorkspace(ws, options).architecture.diagnostics.size(), qsizetype(2));
        options.externals = {{QStringLiteral("/scan"), false, QStringLiteral("lidar driver")},
                             {QStringLiteral("/rover/*/outline"), true, QString()}};
        const Recovery r = recoverWorkspace(ws, options);
        QVERIFY2(r.architecture.diagnostics.isEmpty(),
                 qPrintable(r.architecture.diagnostics.value(0).message));
        options.externals = {{QStringLiteral("/**"), true, QString()}};
        const QList<Diagnostic> left = recoverWorkspace(ws, options).architecture.diagnostics;
        QCOMPARE(left.size(), qsizetype(1));
        QCOMPARE(left.front().code, QStringLiteral("topic-unpublished"));
    }

    void judgeEntryPointsAndLeaveToolsOutputsAndBuildingBlocksAlone()
    {
        // check_scope: robot.launch.xml is the one entry point; mapping.launch.py is included
        // only in another mode, lone.launch.py starts one node, and an older copy of the
        // package sits in src/older_copy. See the fixture's comments for what each line tests.
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("check_scope/ws")));
        QCOMPARE(r.launch.entryPoints,
                 (QStringList{QStringLiteral("src/depot/launch/lone.launch.py"),
                              QStringLiteral("src/depot/launch/robot.launch.xml")}));
        QStringList found;
        for (const QList<Diagnostic> *list :
             {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics})
            for (const Diagnostic &d : *list)
                if (d.code != QLatin1String("external-include"))
                    found << QStringLiteral("%1 %2:%3 | %4 | %5")
                                 .arg(d.code, d.evidence.file)
                                 .arg(d.evidence.line)
                                 .arg(d.message, d.contexts.join(QLatin1Char(',')));
        found.sort();
        QCOMPARE(
            found,
            (QStringList{
                QStringLiteral(
                    "duplicate-package src/older_copy/depot/package.xml:3 | The package depot is "
                    "declared twice: here (version 1.0.3) and in src/depot (version 1.2.0). "
                    "colcon refuses to build both; the analysis uses src/depot, the newer "
                    "version, and ignores this copy. Remove one, or put a COLCON_IGNORE file in "
                    "the copy you do not build. | "),
                QStringLiteral("remap-unmatched src/depot/launch/lone.launch.py:10 | The remap "
                               "mapp:=/map matches no port of the nodes it applies to. | "),
                QStringLiteral("topic-unheard src/depot/depot/lidar.py:16 | /lidar publishes "
                               "/scan_raw, which no node started alongside it subscribes to. | "
                               "src/depot/launch/robot.launch.xml"),
                // A building block's open port is reported only when another launch file
                // remaps it: lone.launch.py misspells the rule mapping.launch.py gives.
                QStringLiteral("topic-unpublished src/depot/depot/planner.py:12 | /planner "
                               "subscribes to /map, which no node started alongside it "
                               "publishes. src/depot/launch/mapping.launch.py:10 remaps it "
                               "(map:=/slam/map) where it starts a node with this port; this "
                               "launch file may be missing that remap. | "
                               "src/depot/launch/lone.launch.py"),
                QStringLiteral("topic-unpublished src/depot/depot/planner.py:13 | /planner "
                               "subscribes to /odom, which no node started alongside it "
                               "publishes. | src/depot/launch/robot.launch.xml")}));
        // The exclusive branches: one scan_mapper is active, the other is kept inactive.
        QStringList mappers;
        for (const NodeInstance &n : r.launch.nodes)
            if (n.nodeName == QLatin1String("scan_mapper"))
                mappers << QStringLiteral("%1 %2").arg(n.evidence.line).arg(n.active);
        QCOMPARE(mappers, (QStringList{QStringLiteral("20 1"), QStringLiteral("21 0")}));
        // The alternatives on an argument nobody sets run only by the best guess.
        QStringList backups;
        for (const NodeInstance &n : r.launch.nodes)
            if (n.nodeName == QLatin1String("backup_mapper"))
                backups << QStringLiteral("%1 %2 %3")
                               .arg(n.evidence.line)
                               .arg(n.active)
                               .arg(n.activeByGuess);
        QCOMPARE(backups, (QStringList{QStringLiteral("24 1 1"), QStringLiteral("25 1 1")}));
    }

private:
    Recovery m_recovery;
    QList<Diagnostic> m_diagnostics;
};

QTEST_GUILESS_MAIN(TestArchitectureChecks)
#include "tst_architecturechecks.moc"
