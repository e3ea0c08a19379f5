// Corrections made through the GUI: each kind through the controller's menu path
// with the dialog filled in as a person would, undone and redone, as the views show it.
#include "support/acceptedwait.h"
#include "support/correctiongui.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test;
using Element = CorrectionController::Element;
using EKind = CorrectionController::Element::Kind;

class TestCorrections : public CorrectionTestBase
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { setUpFixture(); }
    void init() { forgetProjects(); }

    void renameInstanceFromTheLaunchTree()
    {
        auto gui = open();
        const QString id = gui->instanceId(QStringLiteral("safety_monitor"));
        QVERIFY(!id.isEmpty());
        // the launch tree's context menu offers it
        QMenu menu;
        Q_EMIT gui->launchPanel.contextMenuRequested(&menu, gui->launchModel.nodeIndex(id));
        QStringList texts;
        for (QAction *a : menu.actions())
            texts.append(a->text());
        QVERIFY2(texts.contains(QStringLiteral("Re&name\u2026")), qPrintable(texts.join(u'|')));
        QVERIFY(texts.contains(QStringLiteral("Add &Connection\u2026")));
        gui->answer = [](CorrectionDialog &d) {
            if (d.name() != QLatin1String("safety_monitor"))
                return false; // the dialog starts from the current name
            d.setName(QStringLiteral("safety"));
            d.setReason(QStringLiteral("deployed name"));
            return true;
        };
        const auto rename =
            std::find_if(menu.actions().cbegin(), menu.actions().cend(),
                         [](QAction *a) { return a->text().startsWith("Re&name"); });
        (*rename)->trigger();
        QCOMPARE(gui->asked, QStringList{QStringLiteral("Rename")});
        QCOMPARE(gui->document.session()->corrections().size(), 1);
        const Correction &c = gui->document.session()->corrections().first();
        QCOMPARE(c.kind, Correction::Kind::Rename);
        QCOMPARE(c.target,
                 QStringLiteral("instance:src/cart_base/launch/cart.launch.py|safety_monitor"));
        QCOMPARE(c.reason, QStringLiteral("deployed name"));
        QCOMPARE(c.author, QStringLiteral("tester"));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->launchModel.nodeIndex(id).data().toString(),
                     done ? QStringLiteral("safety") : QStringLiteral("safety_monitor"));
            QCOMPARE(gui->launchModel.nodeIndex(id).data(LaunchTreeModel::ProvenanceRole),
                     QVariant(done ? QStringLiteral("corrected") : QStringLiteral("recovered")));
            QCOMPARE(gui->launchModel.nodeIndex(id)
                         .data(Qt::ToolTipRole)
                         .toString()
                         .contains(QStringLiteral("Corrected by c1")),
                     done);
            QCOMPARE(gui->instance(QStringLiteral("safety")) != nullptr, done);
        });
    }

    void renameSetNameAndSetTypeOfPorts()
    {
        auto gui = open();
        const QString ticks = gui->portId(QStringLiteral("OdometryNode"), "wheel_ticks");
        const QString pose =
            gui->portId(QStringLiteral("OdometryNode"), "self.frame_prefix() + '/pose'");
        const QString status = gui->portId(QStringLiteral("OdometryNode"), "status");
        QVERIFY(!ticks.isEmpty() && !pose.isEmpty() && !status.isEmpty());

        // the node list offers Set Name for the expression, Rename for a literal, and Set Type
        // marked unknown for a type analysis could not decide
        const auto texts = [&](const QString &id) {
            QStringList out;
            for (QAction *a : gui->controller->actionsFor({EKind::Port, id, {}, {}}, &gui->window))
                out.append(a->text());
            return out;
        };
        QVERIFY(texts(pose).contains(QStringLiteral("Set &Name\u2026")));
        QVERIFY(texts(ticks).contains(QStringLiteral("Re&name\u2026")));
        QVERIFY2(texts(status).contains(QStringLiteral("Set &Type\u2026 (unknown)")),
                 qPrintable(texts(status).join(u'|')));
        QVERIFY(texts(ticks).contains(QStringLiteral("Set &Type\u2026")));

        // F2 on a port row renames it
        gui->nodePanel.selectSourceIndex(
            gui->nodeModel.portIndex(ticks.section(u'/', 0, 0), ticks.section(u'/', 1)));
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("wheel/ticks"));
            return true;
        };
        Q_EMIT gui->nodePanel.renameRequested(gui->nodePanel.currentSourceIndex());
        QCOMPARE(gui->document.session()->corrections().last().kind, Correction::Kind::Rename);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portRow(ticks),
                     done ? QStringLiteral("wheel/ticks") : QStringLiteral("wheel_ticks"));
        });

        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("/cart/pose"));
            return true;
        };
        QVERIFY(gui->controller->editor()->rename({EKind::Port, pose, {}, {}}));
        QCOMPARE(gui->asked.last(), QStringLiteral("Set Name"));
        QCOMPARE(gui->document.session()->corrections().last().kind, Correction::Kind::SetName);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portRow(pose), done ? QStringLiteral("/cart/pose")
                                              : QStringLiteral("self.frame_prefix() + '/pose'"));
        });

        gui->answer = [](CorrectionDialog &d) {
            if (d.isComplete()) // an unknown type is not offered as the answer
                return false;
            d.setType(QStringLiteral("diagnostic_msgs/msg/DiagnosticStatus"));
            return true;
        };
        QVERIFY(gui->controller->editor()->setType({EKind::Port, status, {}, {}}));
        QCOMPARE(gui->document.session()->corrections().last().kind, Correction::Kind::SetType);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portType(status) == QLatin1String("diagnostic_msgs/msg/DiagnosticStatus"),
                     done);
        });
        QCOMPARE(gui->document.session()->corrections().size(), 3);
        // a later correction of a renamed port names it as it is now
        gui->answer = [](CorrectionDialog &d) {
            d.setType(QStringLiteral("std_msgs/msg/Int64"));
            return true;
        };
        QVERIFY(gui->controller->editor()->setType({EKind::Port, ticks, {}, {}}));
        QVERIFY(gui->document.session()->orphans().isEmpty());
        QCOMPARE(gui->portType(ticks), QStringLiteral("std_msgs/msg/Int64"));
    }

    void removeClassPortInstanceAndConnection()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setReason(QStringLiteral("bench only"));
            return true;
        };
        const QString recorder = gui->classId(QStringLiteral("Recorder"));
        const QModelIndex recorderRow = gui->nodeModel.nodeIndex(recorder);
        // Delete in the node list removes what is current
        gui->nodePanel.selectSourceIndex(recorderRow);
        QAction *del = nullptr;
        for (QAction *a : gui->nodePanel.treeView()->actions())
            if (a->shortcut() == QKeySequence(QKeySequence::Delete))
                del = a;
        QVERIFY(del);
        del->trigger();
        QCOMPARE(gui->document.session()->corrections().size(), 1);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(test::acceptedNow(gui->document).nodes.node(recorder) == nullptr, done);
            // struck out where it was, not hidden
            const QModelIndex row = gui->nodeModel.nodeIndex(recorder);
            QVERIFY(row.isValid());
            QCOMPARE(gui->nodeModel.isRemoved(row), done);
            QCOMPARE(row.data(Qt::FontRole).value<QFont>().strikeOut(), done);
            QCOMPARE(row.data(AtomicNodeModel::ProvenanceRole),
                     QVariant(done ? QStringLiteral("removed") : QStringLiteral("recovered")));
        });
        // a removed element offers only to restore it
        const QList<QAction *> restore =
            gui->controller->actionsFor({EKind::Class, recorder, {}, {}}, &gui->window);
        QCOMPARE(restore.size(), 1);
        QVERIFY(restore.first()->text().startsWith(QStringLiteral("Restore")));
        restore.first()->trigger();
        QVERIFY(gui->document.session()->corrections().isEmpty());
        QVERIFY(test::acceptedNow(gui->document).nodes.node(recorder));
        gui->document.undoStack()->undo(); // the restore
        QVERIFY(!test::acceptedNow(gui->document).nodes.node(recorder));

        const QString odom = gui->portId(QStringLiteral("Recorder"), "odom");
        QVERIFY(gui->controller->editor()->remove(
            {EKind::Port, gui->portId("SafetyMonitor", "reset_estop"), {}, {}}));
        QCOMPARE(gui->document.session()->corrections().last().target,
                 QStringLiteral("port:cart_base|cart_base.safety.SafetyMonitor|service_server|"
                                "reset_estop"));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portNames(QStringLiteral("SafetyMonitor")).contains("reset_estop"),
                     true); // still listed, struck out
            QCOMPARE(gui->portId("SafetyMonitor", "reset_estop").isEmpty(), done);
        });
        Q_UNUSED(odom);

        const QString recorderInstance = gui->instanceId(QStringLiteral("recorder"));
        QVERIFY(gui->controller->editor()->remove({EKind::Instance, recorderInstance, {}, {}}));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->instance(QStringLiteral("recorder")) == nullptr, done);
            QVERIFY(gui->launchNodes().contains(QStringLiteral("recorder")));
            QCOMPARE(gui->launchModel.isRemoved(gui->launchModel.nodeIndex(recorderInstance)),
                     done);
        });

        // a connection from the diagram: the odometry instance's odom publisher
        const QString odometry = gui->instanceId(QStringLiteral("odometry"));
        const QString odomPort = gui->portId(QStringLiteral("OdometryNode"), "odom");
        const auto connected = [&] {
            for (const Composite &c : test::acceptedNow(gui->document).architecture.composites)
                for (const RosNodePart &p : c.parts)
                    if (p.instanceId == odometry)
                        return std::any_of(
                            p.ports.cbegin(), p.ports.cend(),
                            [&](const PartPort &pp) { return pp.id == odomPort.section(u'/', 1); });
            return false;
        };
        QVERIFY(connected());
        QVERIFY(gui->controller->editor()->remove({EKind::Connection, odometry, odomPort, {}}));
        QVERIFY(!gui->document.session()->corrections().last().port.isEmpty());
        roundTrip(*gui, [&](bool done) { QCOMPARE(connected(), !done); });
        QVERIFY(gui->document.session()->orphans().isEmpty());
    }

    void addPortPartAndConnection()
    {
        auto gui = open();
        const QString safety = gui->classId(QStringLiteral("SafetyMonitor"));
        gui->answer = [](CorrectionDialog &d) {
            d.setPortKind(PortKind::Subscriber);
            d.setName(QStringLiteral("sensors/bumper"));
            d.setType(QStringLiteral("std_msgs/msg/Bool"));
            return true;
        };
        QVERIFY(gui->controller->editor()->addPort({EKind::Class, safety, {}, {}}));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portNames(QStringLiteral("SafetyMonitor")).contains("sensors/bumper"),
                     done);
        });
        const QString added = gui->portId(QStringLiteral("SafetyMonitor"), "sensors/bumper");
        QCOMPARE(gui->nodeModel.portIndex(added.section(u'/', 0, 0), added.section(u'/', 1))
                     .data(AtomicNodeModel::ProvenanceRole),
                 QVariant(QStringLiteral("corrected")));
        QCOMPARE(gui->controller->presenter()->describe({EKind::Port, added, {}, {}}).provenance,
                 QStringLiteral("corrected by c1"));

        // Add Part on a launch file: pick a class among the workspace's
        const QString cart = gui->launchFileId(QStringLiteral("cart.launch.py"));
        gui->answer = [](CorrectionDialog &d) {
            if (!d.setChoice(QStringLiteral("class:cart_base|cart_base.safety.SafetyMonitor")))
                return false;
            d.setName(QStringLiteral("watchdog"));
            return true;
        };
        QVERIFY(gui->controller->editor()->addPart({EKind::LaunchFile, cart, {}, {}}));
        QCOMPARE(gui->document.session()->corrections().last().target,
                 QStringLiteral("launch:src/cart_base/launch/cart.launch.py"));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->launchNodes().contains(QStringLiteral("watchdog")), done);
            QCOMPARE(gui->instance(QStringLiteral("watchdog")) != nullptr, done);
        });

        // Add Connection on an instance
        const QString odometry = gui->instanceId(QStringLiteral("odometry"));
        gui->answer = [](CorrectionDialog &d) {
            d.setPortKind(PortKind::Publisher);
            d.setName(QStringLiteral("cart/heartbeat")); // made absolute
            d.setType(QStringLiteral("std_msgs/msg/Empty"));
            return true;
        };
        QVERIFY(gui->controller->editor()->addConnection({EKind::Instance, odometry, {}, {}}));
        QCOMPARE(gui->document.session()->corrections().last().newValue,
                 QStringLiteral("/cart/heartbeat"));
        roundTrip(*gui, [&](bool done) {
            bool found = false;
            for (const Composite &c : test::acceptedNow(gui->document).architecture.composites)
                for (const RosNodePart &p : c.parts)
                    for (const PartPort &pp : p.ports)
                        found = found || (p.instanceId == odometry &&
                                          pp.name == QLatin1String("/cart/heartbeat"));
            QCOMPARE(found, done);
        });
        QVERIFY(gui->document.session()->orphans().isEmpty());
    }

    void renameTopicGroupAndReview()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("/emergency_stop"));
            return true;
        };
        QVERIFY(gui->controller->editor()->rename(
            {EKind::Channel, QStringLiteral("topic:/estop"), {}, {}}));
        const auto hasChannel = [&](const QString &name) {
            for (const Composite &c : test::acceptedNow(gui->document).architecture.composites)
                for (const Channel &ch : c.channels)
                    if (ch.name == name)
                        return true;
            return false;
        };
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(hasChannel(QStringLiteral("/emergency_stop")), done);
            QCOMPARE(hasChannel(QStringLiteral("/estop")), !done);
        });
        // renamed again: from where it came from, so that it stays one rename of /estop
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("/e_stop"));
            return true;
        };
        QVERIFY(gui->controller->editor()->rename(
            {EKind::Channel, QStringLiteral("topic:/emergency_stop"), {}, {}}));
        QCOMPARE(gui->document.session()->corrections().last().target,
                 QStringLiteral("topic:/estop"));
        QVERIFY(hasChannel(QStringLiteral("/e_stop")));

        // group two parts of the root
        const QString root = gui->launchFileId(QStringLiteral("cart.launch.py"));
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("Motion safety"));
            return true;
        };
        QVERIFY(gui->controller->editor()->group(
            {gui->instanceId("odometry"), gui->instanceId("safety_monitor")}, root));
        roundTrip(*gui, [&](bool done) {
            bool grouped = false;
            for (const Composite &c : test::acceptedNow(gui->document).architecture.composites)
                for (const RosNodePart &p : c.parts)
                    grouped = grouped || p.subsystem == QLatin1String("Motion safety");
            QCOMPARE(grouped, done);
        });

        // review: at once, a ✓ in the views; again removes the mark
        const QString odometryNode = gui->classId(QStringLiteral("OdometryNode"));
        const int before = int(gui->document.session()->corrections().size());
        QVERIFY(gui->controller->editor()->toggleReviewed({EKind::Class, odometryNode, {}, {}}));
        QCOMPARE(gui->asked.size(), 3); // no dialog for a review
        roundTrip(*gui, [&](bool done) {
            const QModelIndex row = gui->nodeModel.nodeIndex(odometryNode);
            QCOMPARE(row.data(AtomicNodeModel::ReviewedRole).toBool(), done);
            QCOMPARE(row.data().toString(),
                     done ? QStringLiteral("OdometryNode \u2713") : QStringLiteral("OdometryNode"));
        });
        QVERIFY(gui->controller->editor()->toggleReviewed({EKind::Class, odometryNode, {}, {}}));
        QCOMPARE(int(gui->document.session()->corrections().size()), before);
        const QString odometry = gui->instanceId(QStringLiteral("odometry"));
        QVERIFY(gui->controller->editor()->toggleReviewed({EKind::Instance, odometry, {}, {}}));
        QVERIFY(test::acceptedSettled(gui->document));
        QVERIFY(gui->launchModel.nodeIndex(odometry).data(LaunchTreeModel::ReviewedRole).toBool());
        QVERIFY(
            gui->controller->presenter()->describe({EKind::Instance, odometry, {}, {}}).reviewed);
    }

    void cancelledDialogChangesNothing()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("x"));
            return false;
        };
        QVERIFY(!gui->controller->editor()->rename(
            {EKind::Instance, gui->instanceId(QStringLiteral("odometry")), {}, {}}));
        QVERIFY(gui->document.session()->corrections().isEmpty());
        QCOMPARE(gui->document.undoStack()->count(), 0);
    }
};

QTEST_MAIN(TestCorrections)
#include "tst_corrections.moc"
