// Stage 3: name resolution, guards, wiring, promotion across includes and the architecture
// checks, on hand-built instances and on tests/data/compose_system (two includes of one
// launch file under different namespaces, a container with its own remaps, a guarded
// service, a parameter-derived topic, SetRemap, an inactive node and an unresolved name).
#include "compose/composearchitecture.h"
#include "compose/composer.h"
#include "core/rosnames.h"
#include "pipeline/recovery.h"
#include "plantuml/ccdwriter.h"
#include "support/guifixture.h"
#include "support/testsupport.h"

#include <QtTest>

#include <algorithm>
#include <mutex>

using namespace rosarch;

namespace {

const RosNodePart *partNamed(const Composite &c, const QString &name)
{
    for (const RosNodePart &p : c.parts)
        if (p.name == name || (p.name.isEmpty() && p.typeName == name))
            return &p;
    return nullptr;
}

const PartPort *portOf(const RosNodePart *part, const QString &id)
{
    if (!part)
        return nullptr;
    for (const PartPort &p : part->ports)
        if (p.id == id)
            return &p;
    return nullptr;
}

QStringList connectionsOf(const Composite &c, const QString &targetId)
{
    QStringList out;
    for (const Connection &k : c.connections)
        if (k.targetId == targetId)
            out << QStringLiteral("%1 %2.%3")
                       .arg(connectionKindName(k.kind),
                            c.part(k.partId)->name.isEmpty() ? c.part(k.partId)->typeName
                                                             : c.part(k.partId)->name,
                            k.portId);
    return out;
}

QStringList codes(const QList<Diagnostic> &list)
{
    QStringList out;
    for (const Diagnostic &d : list)
        out << d.code;
    out.sort();
    return out;
}

} // namespace

class TestComposition : public QObject
{
    Q_OBJECT

    Recovery m_recovery;
    const Composite *m_system = nullptr;
    const Composite *m_front = nullptr;
    const Composite *m_rear = nullptr;

private Q_SLOTS:
    void initTestCase()
    {
        m_recovery = recoverWorkspace(test::dataDir(QStringLiteral("compose_system/ws")));
        const Architecture &arch = m_recovery.architecture;
        QCOMPARE(arch.composites.size(), 3);
        m_system = &arch.composites.at(0);
        m_front = &arch.composites.at(1);
        m_rear = &arch.composites.at(2);
        QCOMPARE(m_system->stem, QStringLiteral("system"));
        QCOMPARE(m_front->stem, QStringLiteral("vision"));
        QCOMPARE(m_front->parentId, m_system->instanceId);
    }

    void expandsNames_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("ns");
        QTest::addColumn<QString>("expected");
        QTest::newRow("absolute") << "/scan"
                                  << "/robot"
                                  << "/scan";
        QTest::newRow("relative") << "scan"
                                  << "/robot"
                                  << "/robot/scan";
        QTest::newRow("relative at root") << "scan"
                                          << "/"
                                          << "/scan";
        QTest::newRow("nested relative") << "camera/image"
                                         << "/a/b"
                                         << "/a/b/camera/image";
        QTest::newRow("private") << "~/status"
                                 << "/robot"
                                 << "/robot/driver/status";
        QTest::newRow("private at root") << "~/status"
                                         << "/"
                                         << "/driver/status";
        QTest::newRow("tilde alone") << "~"
                                     << "/robot"
                                     << "/robot/driver";
    }

    void expandsNames()
    {
        QFETCH(QString, name);
        QFETCH(QString, ns);
        QFETCH(QString, expected);
        QCOMPARE(RosNames::expand(name, ns, QStringLiteral("driver")), expected);
    }

    void remapsTheNameAsWritten()
    {
        const QList<QPair<QString, QString>> rules{
            {QStringLiteral("__ns"), QStringLiteral("/x")},
            {QStringLiteral("/robot/scan"), QStringLiteral("scan_raw")},
            {QStringLiteral("~/out"), QStringLiteral("/result")},
            {QStringLiteral("scan"), QStringLiteral("never_used")}};
        int used = -1;
        // "scan" expands to /robot/scan, which the absolute rule names: the first match wins.
        QCOMPARE(RosNames::remap(QStringLiteral("scan"), rules, QStringLiteral("/robot"),
                                 QStringLiteral("n"), &used),
                 QStringLiteral("/robot/scan_raw"));
        QCOMPARE(used, 1);
        QCOMPARE(RosNames::remap(QStringLiteral("~/out"), rules, QStringLiteral("/robot"),
                                 QStringLiteral("n"), &used),
                 QStringLiteral("/result"));
        QCOMPARE(used, 2);
        QCOMPARE(RosNames::remap(QStringLiteral("other"), rules, QStringLiteral("/robot"),
                                 QStringLiteral("n"), &used),
                 QStringLiteral("/robot/other"));
        QCOMPARE(used, -1);

        // A rule for one node ("node:from") applies to that node only.
        const QList<QPair<QString, QString>> nodeRules{
            {QStringLiteral("other_node:cmd"), QStringLiteral("wrong")},
            {QStringLiteral("n:cmd"), QStringLiteral("/mine")}};
        QCOMPARE(RosNames::remap(QStringLiteral("cmd"), nodeRules, QStringLiteral("/robot"),
                                 QStringLiteral("n"), &used),
                 QStringLiteral("/mine"));
        QCOMPARE(used, 1);
        // The reverse of the first case: an absolute name in code, a relative rule.
        const QList<QPair<QString, QString>> relative{
            {QStringLiteral("cmd_vel"), QStringLiteral("safe/cmd_vel")}};
        QCOMPARE(RosNames::remap(QStringLiteral("/robot/cmd_vel"), relative,
                                 QStringLiteral("/robot"), QStringLiteral("n")),
                 QStringLiteral("/robot/safe/cmd_vel"));
        // A file analysed on its own stands at the root: an absolute rule matches its relative
        // name, and the name stays relative when no rule applies.
        const QString scope = QLatin1String(RosNames::kClassifierScope);
        const QList<QPair<QString, QString>> absolute{
            {QStringLiteral("/robo/cmd_vel"), QStringLiteral("/mux/cmd_vel")}};
        QCOMPARE(
            RosNames::remap(QStringLiteral("robo/cmd_vel"), absolute, scope, QStringLiteral("n")),
            QStringLiteral("/mux/cmd_vel"));
        QCOMPARE(RosNames::scopeRelative(RosNames::remap(QStringLiteral("robo/other"), absolute,
                                                         scope, QStringLiteral("n"))),
                 QStringLiteral("robo/other"));
    }

    void evaluatesGuards_data()
    {
        QTest::addColumn<QString>("guard");
        QTest::addColumn<QString>("value");
        QTest::addColumn<bool>("known");
        QTest::addColumn<bool>("holds");
        QTest::newRow("true") << "use_x"
                              << "true" << true << true;
        QTest::newRow("False") << "use_x"
                               << "False" << true << false;
        QTest::newRow("negated") << "!use_x"
                                 << "false" << true << true;
        QTest::newRow("python not") << "not self.use_x"
                                    << "True" << true << false;
        QTest::newRow("member") << "this->use_x_"
                                << "1" << true << true;
        QTest::newRow("compared") << "use_x == false"
                                  << "false" << true << true;
        QTest::newRow("python read in place") << "self.get_parameter('use_x').value"
                                              << "False" << true << false;
        QTest::newRow("negated read in place") << "not self.get_parameter(\"use_x\").value"
                                               << "false" << true << true;
        QTest::newRow("cpp read in place") << "this->get_parameter(\"use_x\").as_bool()"
                                           << "true" << true << true;
        QTest::newRow("read in place, compound") << "self.get_parameter('a').value and ready"
                                                 << "true" << false << true;
        QTest::newRow("compound") << "use_x && ready"
                                  << "true" << false << true;
        QTest::newRow("not a bool") << "use_x"
                                    << "maybe" << false << true;
        // a negation of a parenthesised guard, as an else branch is recorded
        QTest::newRow("negated in parentheses") << "!(is_stamped_)"
                                                << "true" << true << false;
        QTest::newRow("double negation") << "!(!(use_x))"
                                         << "true" << true << true;
        // string and number parameters compared with a literal
        QTest::newRow("string equal") << "mode_ == \"fast\""
                                      << "fast" << true << true;
        QTest::newRow("string unequal") << "(mode_ != 'fast')"
                                        << "fast" << true << false;
        QTest::newRow("negated comparison") << "!(mode_ == \"slow\")"
                                            << "fast" << true << true;
        QTest::newRow("number") << "rate != 0"
                                << "0.0" << true << false;
        QTest::newRow("compared with an expression") << "mode_ == other_"
                                                     << "fast" << false << true;
    }

    void evaluatesGuards()
    {
        QFETCH(QString, guard);
        QFETCH(QString, value);
        QFETCH(bool, known);
        QFETCH(bool, holds);
        bool k = !known;
        QCOMPARE(RosNames::evaluateGuard(guard, value, &k), holds);
        QCOMPARE(k, known);
    }

    void resolvesPortsPerInstance()
    {
        const RosNodePart *camera = partNamed(*m_front, QStringLiteral("front_camera"));
        QVERIFY(camera);
        QCOMPARE(camera->nameSpace, QStringLiteral("/front"));
        QCOMPARE(portOf(camera, QStringLiteral("p1"))->name, QStringLiteral("/front/camera/image"));
        QVERIFY(portOf(camera, QStringLiteral("p1"))->remapped);
        QCOMPARE(portOf(camera, QStringLiteral("ps1"))->name,
                 QStringLiteral("/front/front_camera/set_exposure"));
        QVERIFY(portOf(camera, QStringLiteral("ps1"))->active);

        // The rear include passes exposure:=false: the guarded service is kept but inactive.
        const RosNodePart *rearCamera = partNamed(*m_rear, QStringLiteral("rear_camera"));
        QVERIFY(rearCamera);
        QVERIFY(!portOf(rearCamera, QStringLiteral("ps1"))->active);

        // Container-level remap (image_rect -> rectified) reaches the parameter-derived output.
        const PartPort *rectified =
            portOf(partNamed(*m_front, QStringLiteral("rectifier")), QStringLiteral("p1"));
        QCOMPARE(rectified->name, QStringLiteral("/front/rectified"));
        QVERIFY(rectified->parameterDerived);
        QCOMPARE(
            portOf(partNamed(*m_front, QStringLiteral("detector")), QStringLiteral("s1"))->name,
            QStringLiteral("/front/rectified"));
        // SetRemap in the rear group renames an absolute name inside the included file.
        QCOMPARE(portOf(partNamed(*m_rear, QStringLiteral("detector")), QStringLiteral("p1"))->name,
                 QStringLiteral("/rear/detections"));
        // An expression stays unresolved, with its text as the guess, and is not wired.
        const PartPort *report =
            portOf(partNamed(*m_system, QStringLiteral("commander")), QStringLiteral("p2"));
        QVERIFY(!report->resolved);
        QCOMPARE(report->name, QStringLiteral("f'report_{id(self)}'"));
        for (const Connection &k : m_system->connections)
            QVERIFY(!(k.portId == QLatin1String("p2") &&
                      m_system->part(k.partId)->name == QLatin1String("commander")));
    }

    void wiresInsideAndPromotesTheRest()
    {
        QStringList channels;
        for (const Channel &ch : m_front->channels)
            channels << ch.name;
        QCOMPARE(channels, (QStringList{QStringLiteral("/front/camera/image"),
                                        QStringLiteral("/front/rectified")}));
        QStringList boundary;
        for (const BoundaryPort &b : m_front->boundary)
            boundary << QStringLiteral("%1 %2 %3")
                            .arg(b.id, b.isInput() ? QStringLiteral("in") : QStringLiteral("out"),
                                 b.name);
        QCOMPARE(boundary, (QStringList{QStringLiteral("s1 in /front/trigger"),
                                        QStringLiteral("ps1 in /front/front_camera/set_exposure"),
                                        QStringLiteral("p1 out /detections"),
                                        QStringLiteral("rs1 out /front/get_calibration")}));
        // The rear composite has no exposure service to promote.
        QCOMPARE(m_rear->boundary.size(), 3);
    }

    void containersAreNotParts()
    {
        // The component container is deployment (blueprint §1): its components are parts and
        // record it; the container itself is not a part.
        QStringList parts;
        for (const RosNodePart &p : m_front->parts)
            parts << p.name;
        QCOMPARE(parts, (QStringList{QStringLiteral("front_camera"), QStringLiteral("rectifier"),
                                     QStringLiteral("detector")}));
        for (const QString &component : {QStringLiteral("rectifier"), QStringLiteral("detector")}) {
            const NodeInstance *n =
                m_recovery.launch.node(partNamed(*m_front, component)->instanceId);
            QVERIFY(n);
            const NodeInstance *host = m_recovery.launch.node(n->container);
            QVERIFY(host);
            QCOMPARE(host->nodeName, QStringLiteral("vision_container"));
        }
    }

    void wiresAcrossIncludes()
    {
        const RosNodePart *front = nullptr;
        for (const RosNodePart &p : m_system->parts)
            if (p.kind == RosNodePart::Kind::Launch && p.typeId == m_front->instanceId)
                front = &p;
        QVERIFY(front);
        QCOMPARE(front->nameSpace, QStringLiteral("/front"));
        QCOMPARE(front->ports.size(), m_front->boundary.size());

        const Channel *detections = nullptr;
        for (const Channel &ch : m_system->channels)
            if (ch.name == QLatin1String("/detections"))
                detections = &ch;
        QVERIFY(detections);
        QCOMPARE(connectionsOf(*m_system, detections->id),
                 (QStringList{QStringLiteral("publish vision.p1"),
                              QStringLiteral("subscribe planner.s1"),
                              QStringLiteral("subscribe backup_planner.s1")}));
        // The planners' relative front/trigger reaches the front camera's promoted subscription.
        QCOMPARE(connectionsOf(*m_system, QStringLiteral("q_front_trigger")),
                 (QStringList{QStringLiteral("publish planner.p2"),
                              QStringLiteral("publish backup_planner.p2"),
                              QStringLiteral("subscribe vision.s1")}));
        QCOMPARE(connectionsOf(*m_system, QStringLiteral("a_navigate")),
                 (QStringList{QStringLiteral("server planner.pa1"),
                              QStringLiteral("server backup_planner.pa1"),
                              QStringLiteral("client commander.ra1")}));
        // Three publishers of /robot/cmd_vel and no subscriber: delegation is one to one
        // (blueprint §1), so three boundary ports, each with one delegation and its own type.
        QStringList cmd;
        for (const BoundaryPort &b : m_system->boundary)
            if (b.name == QLatin1String("/robot/cmd_vel")) {
                QCOMPARE(connectionsOf(*m_system, b.id).size(), 1);
                cmd << b.id + QLatin1Char(' ') + b.type;
            }
        QCOMPARE(cmd, (QStringList{QStringLiteral("p2 geometry_msgs/msg/Twist"),
                                   QStringLiteral("p3 geometry_msgs/msg/Twist"),
                                   QStringLiteral("p4 geometry_msgs/msg/TwistStamped")}));
    }

    void inactivePartsAreKeptButNotWired()
    {
        const RosNodePart *sim = partNamed(*m_system, QStringLiteral("sim_commander"));
        QVERIFY(sim);
        QVERIFY(!sim->active);
        for (const Connection &k : m_system->connections)
            QVERIFY(k.partId != sim->id);
        QVERIFY(!CcdWriter::write(*m_system).contains(QLatin1String("sim_commander")));
    }

    void reportsArchitectureChecks()
    {
        const QList<Diagnostic> &d = m_recovery.architecture.diagnostics;
        QCOMPARE(
            codes(d),
            (QStringList{QStringLiteral("duplicate-server"), QStringLiteral("duplicate-server"),
                         QStringLiteral("remap-unmatched"), QStringLiteral("type-mismatch")}));
        // The ports the system leaves open (the planners' cmd_vel remapped to a topic nobody
        // subscribes to, a camera's input from a driver) have no evidence of a mistake: they
        // are the system's boundary, not findings (see tst_architecturechecks).
        for (const Diagnostic &x : d) {
            QVERIFY2(x.evidence.isValid(), qPrintable(x.message));
            if (x.code == QLatin1String("remap-unmatched")) {
                QCOMPARE(x.evidence.file, QStringLiteral("src/vision/launch/vision.launch.xml"));
                QVERIFY(x.message.contains(QLatin1String("camera_info:=camera/info")));
            }
            if (x.code == QLatin1String("type-mismatch")) {
                QVERIFY(x.message.contains(
                    QLatin1String("geometry_msgs/msg/Twist, geometry_msgs/msg/TwistStamped")));
                // The other side of the mismatch is a related location.
                QCOMPARE(x.related.size(), 1);
                QCOMPARE(x.related.first().evidence.file,
                         QStringLiteral("src/planning/planning/commander.py"));
                QVERIFY(x.related.first().message.contains(
                    QLatin1String("geometry_msgs/msg/TwistStamped")));
            }
        }
    }

    void theCcdIsTheFileOnItsOwn()
    {
        // vision.launch.xml is included twice, under front and under rear: its CCD is the file
        // analysed on its own (blueprint §1), the same whoever includes it, with its relative
        // names relative; every instance's composite points to it.
        const QList<const Composite *> reps = m_recovery.architecture.representatives();
        QCOMPARE(reps.size(), 2);
        const Composite *vision = reps.at(1);
        QCOMPARE(vision->file, m_front->file);
        QVERIFY(vision->instanceId.startsWith(QLatin1Char('c'))); // a classifier, not an instance
        QVERIFY(vision->parentId.isEmpty());
        QCOMPARE(vision->parts.size(), m_front->parts.size());
        for (const RosNodePart &p : vision->parts)
            QVERIFY2(p.nameSpace.isEmpty(), qPrintable(p.nameSpace));
        QStringList channels;
        for (const Channel &ch : vision->channels)
            channels << ch.name;
        QCOMPARE(channels,
                 (QStringList{QStringLiteral("camera/image"), QStringLiteral("rectified")}));
        const QString ccd = CcdWriter::write(*vision);
        QVERIFY(!ccd.contains(QLatin1String("front/")));
        QVERIFY(!ccd.contains(QLatin1String("rear")) &&
                !ccd.contains(QLatin1String("<<namespace>>")));
        QVERIFY(ccd.contains(QLatin1String("/detections"))); // absolute in the file: stays
        // The instances keep their own resolution, and point to the one CCD.
        QStringList frontChannels;
        for (const Channel &ch : m_front->channels)
            frontChannels << ch.name;
        QVERIFY(frontChannels.contains(QStringLiteral("/front/camera/image")));
        const QMap<QString, QString> stems = CcdWriter::fileStems(m_recovery.architecture);
        QCOMPARE(stems.value(vision->instanceId), QStringLiteral("vision"));
        QCOMPARE(stems.value(m_front->instanceId), QStringLiteral("vision"));
        int visionInstances = 0;
        for (const Composite &c : m_recovery.architecture.composites)
            if (c.file == vision->file) {
                ++visionInstances;
                QCOMPARE(stems.value(c.instanceId), QStringLiteral("vision"));
            }
        QCOMPARE(visionInstances, 2);
    }

    void cancelStopsTheStage()
    {
        StageControl control;
        control.canceled = [] { return true; };
        const Architecture arch = Composer::run(m_recovery.nodes, m_recovery.launch, control);
        QVERIFY(arch.canceled);
        QVERIFY(arch.composites.isEmpty());
    }

    void stemsOfLaunchFiles()
    {
        QCOMPARE(launchStem(QStringLiteral("robot.launch.py")), QStringLiteral("robot"));
        QCOMPARE(launchStem(QStringLiteral("nav_launch.py")), QStringLiteral("nav"));
        QCOMPARE(launchStem(QStringLiteral("a/b/mission.launch.yaml")), QStringLiteral("mission"));
        QCOMPARE(launchStem(QStringLiteral("bringup.xml")), QStringLiteral("bringup"));
    }

    void stageThreeReportsOneProgression()
    {
        // The status bar's bar fills once for stage 3: the systems, then each launch file's own
        // classifier diagram. The two parts report from two threads: in any order, once each.
        const LaunchDependencies &launch = m_recovery.launch;
        QVERIFY(!launch.classifierInstances.isEmpty());
        const int all = int(launch.instances.size() + launch.classifierInstances.size());
        std::mutex mutex;
        QList<std::pair<int, int>> reports;
        StageControl control;
        control.progressed = [&](int done, int total, const QString &) {
            const std::lock_guard lock(mutex);
            reports.append({done, total});
        };
        QVERIFY(composeArchitecture(m_recovery.nodes, launch, control) == m_recovery.architecture);
        std::sort(reports.begin(), reports.end());
        QCOMPARE(reports.size(), all);
        int last = 0;
        for (const auto &[done, total] : std::as_const(reports)) {
            QCOMPARE(total, all);
            QCOMPARE(done, last + 1);
            last = done;
        }
    }

    // An executable's main builds two relays and a display: one instance per construction,
    // named and wired by its own constructor arguments (a default written at the declaration,
    // a __node rule in NodeOptions), in the executable's own composite.
    void nodesBuiltInCodeTakeTheirArguments()
    {
        const Recovery r = recoverWorkspace(test::dataDir(QStringLiteral("cpp_nodes_in_main/ws")));
        const Composite *chain = nullptr;
        for (const Composite &c : r.architecture.composites)
            if (c.executable == QLatin1String("relay_chain"))
                chain = &c;
        QVERIFY(chain);
        QStringList parts;
        for (const RosNodePart &p : chain->parts) {
            QStringList ports;
            for (const PartPort &pp : p.ports)
                ports << pp.name;
            parts << p.name + u' ' + p.typeName + u' ' + ports.join(u',');
        }
        // in the order main() builds them
        QCOMPARE(parts, (QStringList{QStringLiteral("first_relay RelayStage /marked_copy,/frames"),
                                     QStringLiteral("relay RelayStage /marked_frames,/marked_copy"),
                                     QStringLiteral("chain_display DisplayStage /marked_frames")}));
        QStringList channels;
        for (const Channel &ch : chain->channels)
            channels << ch.name;
        channels.sort();
        QCOMPARE(channels,
                 (QStringList{QStringLiteral("/marked_copy"), QStringLiteral("/marked_frames")}));
    }
};

QTEST_GUILESS_MAIN(TestComposition)
#include "tst_composition.moc"
