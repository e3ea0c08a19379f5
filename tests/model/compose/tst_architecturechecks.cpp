// The architecture checks ROSDiscover's users rely on, on tests/data/check_system: a misspelt
// topic is one finding with the name it misspells as a hint, two nodes share a name, a remap
// sends a subscription to a misspelt topic, and literal QoS that cannot match (Python against
// Python, Python against C++); plus the QoS reading itself and the findings' stable keys. An
// open port with no evidence of a mistake is the system's interface, not a finding.
#include "core/qos.h"
#include "pipeline/recovery.h"
#include "support/recoverytest.h"
#include "support/testsupport.h"

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
        QCOMPARE(
            qos,
            (QStringList{
                QStringLiteral("Base cmd_vel: rclcpp::QoS(rclcpp::KeepLast(1)).reliable()"),
                // the callback before the QoS is skipped
                QStringLiteral("Base map: rclcpp::QoS(1).transient_local()"),
                QStringLiteral("Lidar scan: qos_profile_sensor_data"),
                QStringLiteral("Lidar wheel_odom: 10"), QStringLiteral("Mapper initialpose: 10"),
                QStringLiteral("Mapper map: latched"),
                QStringLiteral("Mapper scan: QoSProfile(depth=5, "
                               "reliability=ReliabilityPolicy.RELIABLE)"),
                QStringLiteral("Mapper whel_odom: 10"),
                QStringLiteral("Teleop cmd_vel: QoSProfile(depth=1, "
                               "reliability=ReliabilityPolicy.BEST_EFFORT)"),
                QStringLiteral("Teleop initialpose: 10"), QStringLiteral("Viewer map: 1"),
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
                         QStringLiteral("topic-unpublished")}));
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
        // The unheard /wheel_odom is the same mistake: one finding, at the subscription that
        // misses its data.
        QVERIFY(ofCode(m_diagnostics, QStringLiteral("topic-unheard")).isEmpty());
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

    void remapToAMisspeltName()
    {
        const Diagnostic d = ofCode(m_diagnostics, QStringLiteral("remap-target-unused")).value(0);
        QCOMPARE(d.severity, Diagnostic::Severity::Warning); // an input nobody feeds
        QVERIFY2(d.message.contains(QLatin1String("initialpose to /initial_pose")),
                 qPrintable(d.message));
        QVERIFY2(d.message.endsWith(QLatin1String("Did you mean /initialpose?")),
                 qPrintable(d.message));
        // The rule is written in the launch file; the port's creation and the publisher of the
        // name it misspells are the related places.
        QCOMPARE(at(d.evidence), QStringLiteral("src/patrol/launch/patrol.launch.py:8"));
        QCOMPARE(at(d.related.value(0).evidence), QStringLiteral("src/patrol/patrol/mapper.py:21"));
        QCOMPARE(at(d.related.value(1).evidence), QStringLiteral("src/patrol/patrol/teleop.py:15"));
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
        // namespace robot1, by fleet, all through planning.launch.py, which lacks the remap of
        // /map that nav.launch.py gives: its unpublished /map is one finding seen in two
        // systems (the same node, the same name), and another one in the third (another name).
        // Its misspelt /odom_raws is one finding in sim and field, which start the odometry
        // that publishes /odom_raw. Fleet's /robot1/odom and /robot1/odom_raws are open too,
        // with no evidence of a mistake there: no finding.
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("check_roots/ws")));
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 | %2 | %3")
                         .arg(d.code, d.message, d.contexts.join(QLatin1Char(',')));
        found.sort();
        const QString launch = QStringLiteral("src/rover/launch/");
        const QString why = QStringLiteral(" %1nav.launch.py:8 remaps it (map:=/slam/map) where "
                                           "it starts a node of the same class; "
                                           "%1planning.launch.py starts this one without that "
                                           "remap.")
                                .arg(launch);
        QCOMPARE(found,
                 (QStringList{QStringLiteral("topic-unpublished | /planner subscribes to /map, "
                                             "which no node started alongside it publishes.%2 | "
                                             "%1field.launch.py,%1sim.launch.py")
                                  .arg(launch, why),
                              QStringLiteral("topic-unpublished | /planner subscribes to "
                                             "/odom_raws, which no node started alongside it "
                                             "publishes. Did you mean /odom_raw? | "
                                             "%1field.launch.py,%1sim.launch.py")
                                  .arg(launch),
                              QStringLiteral("topic-unpublished | /robot1/planner subscribes to "
                                             "/robot1/map, which no node started alongside it "
                                             "publishes.%2 | %1fleet.launch.py")
                                  .arg(launch, why)}));
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
        // The children's grids are heard by the watcher; what stays open (a scan from a
        // driver, an outline for tools) has no evidence of a mistake: no finding.
        QVERIFY2(r.architecture.diagnostics.isEmpty(),
                 qPrintable(r.architecture.diagnostics.value(0).message));
        QCOMPARE(r.launch.viewedTopics.size(), qsizetype(2));
    }

    void namesAnEntryPointTakesAsArgumentsAreItsInterface()
    {
        // launch_root_wiring: avoidance.launch.xml remaps the avoider's input to an argument
        // whose default is /front/range; robot.launch.py wires everything it starts. The
        // simulated range nobody hears in avoidance.launch.xml is open with no evidence of a
        // mistake either.
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("launch_root_wiring/ws")));
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 %2 | %3")
                         .arg(d.code, d.message, d.contexts.join(QLatin1Char(',')));
        QVERIFY2(found.isEmpty(), qPrintable(found.join(u'\n')));
    }

    void libraryPortsAndTheEvidenceOfAMissingRemap()
    {
        // cpp_message_filters (see its README): image_transport, a helper's aliased
        // message_filters subscribers and cuda_blackboard make LaneMarker's ports; the demo
        // launch file misses two remaps the other file gives, and nothing else is judged.
        const Recovery r =
            recoverWorkspace(test::dataDir(QStringLiteral("cpp_message_filters/ws")));
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            found << QStringLiteral("%1 %2:%3 | %4")
                         .arg(d.code, d.evidence.file)
                         .arg(d.evidence.line)
                         .arg(d.message);
        found.sort();
        const QString missing = QStringLiteral(
            " src/pose_fuser/launch/lane_marker.launch.xml:4 remaps it (~/input/%1:=%2) where it "
            "starts a node of the same class; src/pose_fuser/launch/lane_marker_demo.launch.xml "
            "starts this one without that remap.");
        QCOMPARE(found,
                 (QStringList{
                     QStringLiteral("remap-unmatched src/pose_fuser/launch/pose_fuser.launch.xml:2 "
                                    "| The remap ~/input/twist:=/localization/twist matches no "
                                    "port of the nodes it applies to."),
                     QStringLiteral("topic-unpublished src/pose_fuser/include/pose_fuser/"
                                    "paired.hpp:24 | /lane_marker subscribes to "
                                    "/lane_marker/input/camera_info, which no node started "
                                    "alongside it publishes.") +
                         missing.arg(QStringLiteral("camera_info"),
                                     QStringLiteral("/camera/camera_info")),
                     QStringLiteral("topic-unpublished src/pose_fuser/src/lane_marker.cpp:12 | "
                                    "/lane_marker subscribes to /lane_marker/input/image, which "
                                    "no node started alongside it publishes.") +
                         missing.arg(QStringLiteral("image"), QStringLiteral("/camera/image"))}));
    }

    void lazyImageInputsAreThePortsTheirRemapsName()
    {
        // cpp_lazy_image_inputs: inputs made in a matched callback, by resolved names, on
        // members declared together; only the dead remap matches nothing.
        const Recovery r =
            recoverWorkspace(test::dataDir(QStringLiteral("cpp_lazy_image_inputs/ws")));
        QCOMPARE(test::diagnosticsWithCode(r, QStringLiteral("remap-unmatched")),
                 QStringList{QStringLiteral(
                     "src/depth_tools/launch/shaded_cloud.launch.py: The remap "
                     "color/image_rect:=/camera/color/image_raw matches no port of the nodes it "
                     "applies to.")});
    }

    void aSpentHintBudgetIsSaid()
    {
        // A node with 3,000 open inputs of one length beside another node: looking for a
        // misspelt counterpart of each compares every name of a near length, which passes the
        // search's budget; the run says so instead of dropping that evidence silently.
        QTemporaryDir dir;
        QByteArray many = "from rclpy.node import Node\nfrom std_msgs.msg import String\n\n"
                          "class Many(Node):\n    def __init__(self):\n"
                          "        super().__init__('many')\n";
        for (int i = 0; i < 3000; ++i)
            many += QStringLiteral("        self.create_subscription(String, 'in_%1', None, 1)\n")
                        .arg(i, 4, 10, QLatin1Char('0'))
                        .toLatin1();
        test::healthyPythonPackage(dir.path(), "many = pkg.many:main");
        test::writeFile(dir.path() + "/src/pkg/pkg/many.py", many);
        test::writeFile(dir.path() + "/src/pkg/launch/all.launch.xml",
                        "<launch>\n  <node pkg=\"pkg\" exec=\"good\"/>\n"
                        "  <node pkg=\"pkg\" exec=\"many\"/>\n</launch>\n");
        const Recovery r = recoverWorkspace(dir.path());
        QStringList limits;
        for (const Diagnostic &d : r.architecture.diagnostics)
            if (d.code == QLatin1String("check-limit"))
                limits << d.message;
        QCOMPARE(limits, QStringList{QStringLiteral(
                             "The search for misspelt names spent its budget (50000000 letters "
                             "compared) in the system of src/pkg/launch/all.launch.xml: open "
                             "ports judged after that were judged without it, so a misspelling "
                             "may go unreported.")});
        // A system of a few names spends nothing of it.
        QCOMPARE(test::diagnosticsWithCode(
                     recoverWorkspace(test::dataDir(QStringLiteral("check_scope/ws"))),
                     QStringLiteral("check-limit")),
                 QStringList{});
    }

    void aRemapForALaterVersionOfTheNodeSaysSo()
    {
        // A bringup package of version 2.0.0 remaps an input that version 1.0.0 of the node's
        // package does not have yet (two repositories of different releases side by side): the
        // finding says which versions; the same package's own launch file gets no such hint,
        // nor does a rule the node's own package gives too (a leftover in both releases).
        QTemporaryDir dir;
        test::healthyPythonPackage(dir.path());
        test::writeFile(dir.path() + "/src/pkg/package.xml",
                        "<package format=\"3\"><name>pkg</name><version>1.0.0</version><export>"
                        "<build_type>ament_python</build_type></export></package>\n");
        test::writeFile(dir.path() + "/src/pkg/launch/good.launch.xml",
                        "<launch>\n  <node pkg=\"pkg\" exec=\"good\" name=\"good\">\n"
                        "    <remap from=\"in\" to=\"/x\"/>\n  </node>\n</launch>\n");
        test::writeFile(dir.path() + "/src/bringup/package.xml",
                        "<package format=\"3\"><name>bringup</name><version>2.0.0</version>"
                        "<export><build_type>ament_cmake</build_type></export></package>\n");
        test::writeFile(dir.path() + "/src/bringup/launch/robot.launch.xml",
                        "<launch>\n  <node pkg=\"pkg\" exec=\"good\" name=\"good\">\n"
                        "    <remap from=\"status\" to=\"/robot/status\"/>\n"
                        "    <remap from=\"in\" to=\"/robot/x\"/>\n  </node>\n</launch>\n");
        const Recovery r = recoverWorkspace(dir.path());
        QStringList found;
        for (const Diagnostic &d : r.architecture.diagnostics)
            if (d.code == QLatin1String("remap-unmatched"))
                found << d.evidence.file + QStringLiteral(" | ") + d.message;
        found.sort();
        QCOMPARE(
            found,
            (QStringList{QStringLiteral("src/bringup/launch/robot.launch.xml | The remap "
                                        "in:=/robot/x matches no port of the nodes it applies "
                                        "to."),
                         QStringLiteral("src/bringup/launch/robot.launch.xml | The remap "
                                        "status:=/robot/status matches no port of the nodes it "
                                        "applies to. The launch file's package, bringup 2.0.0, is "
                                        "of a newer release than the node's, pkg 1.0.0: the remap "
                                        "may be written for another version of the node."),
                         QStringLiteral("src/pkg/launch/good.launch.xml | The remap in:=/x matches "
                                        "no port of the nodes it applies to.")}));
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
        // The two open-port findings of check_scope (/map and /odom, each missing a remap
        // another launch file gives), declared as expected externals: one by its name, one by
        // a pattern; a declaration of the other direction accepts nothing.
        const QString ws = test::dataDir(QStringLiteral("check_scope/ws"));
        const auto open = [](const Recovery &r) {
            QStringList names;
            for (const Diagnostic &d : r.architecture.diagnostics)
                if (d.code == QLatin1String("topic-unpublished"))
                    names << d.external;
            return names;
        };
        LaunchOptions options;
        QCOMPARE(open(recoverWorkspace(ws, options)),
                 (QStringList{QStringLiteral("input /map"), QStringLiteral("input /odom")}));
        options.externals = {{QStringLiteral("/map"), false, QString()}};
        QCOMPARE(open(recoverWorkspace(ws, options)), QStringList{QStringLiteral("input /odom")});
        options.externals = {{QStringLiteral("/map"), false, QStringLiteral("the SLAM node")},
                             {QStringLiteral("/o*"), false, QString()}};
        QCOMPARE(open(recoverWorkspace(ws, options)), QStringList{});
        options.externals = {{QStringLiteral("/**"), true, QString()}};
        QCOMPARE(open(recoverWorkspace(ws, options)).size(), 2);
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
                // An open port is reported only with evidence of a mistake: here another launch
                // file remaps it. lone.launch.py misspells the rule mapping.launch.py gives, and
                // robot.launch.xml lacks the one lone.launch.py gives. The lidar's /scan_raw,
                // which nobody in robot.launch.xml hears, has no such evidence.
                QStringLiteral("topic-unpublished src/depot/depot/planner.py:12 | /planner "
                               "subscribes to /map, which no node started alongside it "
                               "publishes. src/depot/launch/mapping.launch.py:10 remaps it "
                               "(map:=/slam/map) where it starts a node of the same class; "
                               "src/depot/launch/lone.launch.py starts this one without that "
                               "remap. | src/depot/launch/lone.launch.py"),
                QStringLiteral("topic-unpublished src/depot/depot/planner.py:13 | /planner "
                               "subscribes to /odom, which no node started alongside it "
                               "publishes. src/depot/launch/lone.launch.py:10 remaps it "
                               "(odom:=/wheel/odom) where it starts a node of the same class; "
                               "src/depot/launch/robot.launch.xml starts this one without that "
                               "remap. | src/depot/launch/robot.launch.xml")}));
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

    // An executable whose main builds three nodes, started with name=: ROS 2 names all three
    // so, which is one process-renamed finding at the launch action, not a duplicate name; the
    // same executable started without a name gives none. The executable gets a CCD of its own.
    void nameGivenToAProcessOfSeveralNodes()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("cpp_nodes_in_main/ws")));
        const QList<Diagnostic> &all = r.architecture.diagnostics;
        QCOMPARE(ofCode(all, QStringLiteral("duplicate-node-name")).size(), 0);
        const QList<Diagnostic> renamed = ofCode(all, QStringLiteral("process-renamed"));
        QCOMPARE(renamed.size(), 1);
        QCOMPARE(at(renamed[0].evidence),
                 QStringLiteral("src/yard_pipeline_bringup/launch/pipelines.launch.xml:7"));
        QVERIFY2(
            renamed[0].message.contains(QLatin1String("(CameraStage, DisplayStage, MarkerStage)")),
            qPrintable(renamed[0].message));
        QStringList executables;
        for (const Composite &c : r.architecture.classifiers)
            if (!c.executable.isEmpty())
                executables << c.executable + u' ' + c.file + u' ' +
                                   QString::number(c.channels.size());
        QCOMPARE(executables, QStringList{QStringLiteral(
                                  "pipeline_in_one src/yard_pipeline/src/pipeline_in_one.cpp 2")});
    }
};

QTEST_GUILESS_MAIN(TestArchitectureChecks)
#include "tst_architecturechecks.moc"
