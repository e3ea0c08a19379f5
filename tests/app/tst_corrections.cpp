// Corrections made through the GUI (issue 12): each kind through the controller's menu path
// with the dialog filled in as a person would, undone and redone, as the views show it; the
// Corrections panel; re-running the stages; orphans and re-targeting.
#include "atomicnodemodel.h"
#include "atomicnodepanel.h"
#include "correctioncontroller.h"
#include "correctiondialog.h"
#include "correctionmodel.h"
#include "correctionpanel.h"
#include "diagramlayouter.h"
#include "diagrampanel.h"
#include "document.h"
#include "inspectorpanel.h"
#include "launchtreemodel.h"
#include "launchtreepanel.h"
#include "recovery.h"
#include "sourceview.h"
#include "testsupport.h"
#include "traceability.h"

#include <QAbstractItemModelTester>
#include <QAction>
#include <QDirIterator>
#include <QMenu>
#include <QStandardPaths>
#include <QTableView>
#include <QTemporaryDir>
#include <QTreeView>
#include <QUndoStack>
#include <QtTest>

#include <memory>

using namespace rosarch;
using Element = CorrectionController::Element;
using EKind = CorrectionController::Element::Kind;

namespace {

/// The views and the controller of the main window, on one Document.
struct Gui
{
    Document document;
    AtomicNodeModel nodeModel{&document};
    LaunchTreeModel launchModel{&document};
    CorrectionModel correctionModel{&document};
    AtomicNodePanel nodePanel;
    LaunchTreePanel launchPanel;
    DiagramLayouter layouter;
    DiagramPanel diagramPanel{&layouter};
    SourceView sourceView;
    InspectorPanel inspector;
    CorrectionPanel correctionPanel;
    std::unique_ptr<Traceability> traceability;
    QWidget window;
    std::unique_ptr<CorrectionController> controller;
    std::function<bool(CorrectionDialog &)> answer; ///< the person at the dialog
    QStringList asked;                              ///< the dialogs' titles, in order

    Gui()
    {
        nodePanel.setModel(&nodeModel);
        launchPanel.setModel(&launchModel);
        correctionPanel.setModel(&correctionModel);
        traceability = std::make_unique<Traceability>(&nodeModel, &nodePanel, &launchModel,
                                                      &launchPanel, &sourceView);
        controller = std::make_unique<CorrectionController>(&document, &nodePanel, &launchPanel,
                                                            &diagramPanel, traceability.get(),
                                                            &inspector, &correctionPanel, &window);
        controller->setDialogHandler([this](CorrectionDialog &d) {
            asked.append(d.windowTitle());
            return answer ? answer(d) : false;
        });
        QObject::connect(&document, &Document::changed, &diagramPanel, [this] {
            diagramPanel.setArchitecture(document.accepted().architecture);
        });
    }
    ~Gui() { controller.reset(); }

    QString classId(const QString &className) const
    {
        for (const AtomicNode &n : document.atomicNodes().nodes)
            if (n.className == className)
                return n.id;
        return {};
    }
    QString portId(const QString &className, const QString &name) const
    {
        for (const AtomicNode &n : document.accepted().nodes.nodes)
            if (n.className == className)
                for (const Port &p : n.ports)
                    if (p.name == name || p.nameExpression == name)
                        return n.id + u'/' + p.id;
        return {};
    }
    const NodeInstance *instance(const QString &name) const
    {
        for (const NodeInstance &n : document.accepted().launch.nodes)
            if (n.nodeName == name)
                return &n;
        return nullptr;
    }
    QString instanceId(const QString &name) const
    {
        const NodeInstance *n = instance(name);
        return n ? n->id : QString();
    }
    QString launchFileId(const QString &fileName) const
    {
        for (const LaunchFileInstance &lf : document.accepted().launch.instances)
            if (lf.file.endsWith(fileName))
                return lf.id;
        return {};
    }
    /// What the node list shows in the name column of a port row.
    QString portRow(const QString &id) const
    {
        return nodeModel.portIndex(id.section(u'/', 0, 0), id.section(u'/', 1)).data().toString();
    }
    QString portType(const QString &id) const
    {
        return nodeModel
            .portIndex(id.section(u'/', 0, 0), id.section(u'/', 1), AtomicNodeModel::TypeColumn)
            .data()
            .toString();
    }
    QStringList portNames(const QString &className) const
    {
        QStringList names;
        const QModelIndex node = nodeModel.nodeIndex(classId(className));
        for (int r = 0; r < nodeModel.rowCount(node); ++r)
            names.append(nodeModel.index(r, 0, node).data().toString());
        return names;
    }
    /// The names of the launch tree's node rows under every launch file, in order.
    QStringList launchNodes() const
    {
        QStringList names;
        std::function<void(const QModelIndex &)> walk = [&](const QModelIndex &parent) {
            for (int r = 0; r < launchModel.rowCount(parent); ++r) {
                const QModelIndex i = launchModel.index(r, 0, parent);
                if (launchModel.kind(i) == LaunchTreeModel::ItemKind::Node)
                    names.append(i.data().toString());
                if (launchModel.kind(i) != LaunchTreeModel::ItemKind::Parameters)
                    walk(i);
            }
        };
        walk({});
        return names;
    }
};

bool copyTree(const QString &from, const QString &to)
{
    QDirIterator it(from, QDir::Files | QDir::NoDotAndDotDot, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString target = QDir(to).filePath(QDir(from).relativeFilePath(file));
        if (!QDir().mkpath(QFileInfo(target).path()) || !QFile::copy(file, target))
            return false;
    }
    return true;
}

Recovery recover(const QString &root)
{
    LaunchOptions options;
    options.rootFile = QStringLiteral("src/cart_base/launch/cart.launch.py");
    return recoverWorkspace(root, options);
}

} // namespace

class TestCorrections : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString m_ws;
    Recovery m_recovery;

    std::unique_ptr<Gui> open()
    {
        auto gui = std::make_unique<Gui>();
        gui->document.setRecovery(m_recovery);
        return gui;
    }

    /// Undo and redo the last step; `check(true)` holds after redo, `check(false)` after undo.
    static void roundTrip(Gui &gui, const std::function<void(bool)> &check)
    {
        const Recovery done = gui.document.accepted();
        check(true);
        gui.document.undoStack()->undo();
        check(false);
        gui.document.undoStack()->redo();
        check(true);
        QCOMPARE(gui.document.accepted(), done);
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        qputenv("ROSARCH_AUTHOR", "tester");
        QVERIFY(m_dir.isValid());
        m_ws = m_dir.filePath(QStringLiteral("ws"));
        QVERIFY(copyTree(QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/ws"), m_ws));
        m_recovery = recover(m_ws);
        QVERIFY(!m_recovery.nodes.nodes.isEmpty());
        QVERIFY(!m_recovery.launch.nodes.isEmpty());
    }

    void init()
    {
        // every test starts without a project: the autosave of the last one is not read
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
    }

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
        QCOMPARE(gui->document.corrections().size(), 1);
        const Correction &c = gui->document.corrections().first();
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
        QCOMPARE(gui->document.corrections().last().kind, Correction::Kind::Rename);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portRow(ticks),
                     done ? QStringLiteral("wheel/ticks") : QStringLiteral("wheel_ticks"));
        });

        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("/cart/pose"));
            return true;
        };
        QVERIFY(gui->controller->rename({EKind::Port, pose, {}, {}}));
        QCOMPARE(gui->asked.last(), QStringLiteral("Set Name"));
        QCOMPARE(gui->document.corrections().last().kind, Correction::Kind::SetName);
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
        QVERIFY(gui->controller->setType({EKind::Port, status, {}, {}}));
        QCOMPARE(gui->document.corrections().last().kind, Correction::Kind::SetType);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portType(status) == QLatin1String("diagnostic_msgs/msg/DiagnosticStatus"),
                     done);
        });
        QCOMPARE(gui->document.corrections().size(), 3);
        // a later correction of a renamed port names it as it is now
        gui->answer = [](CorrectionDialog &d) {
            d.setType(QStringLiteral("std_msgs/msg/Int64"));
            return true;
        };
        QVERIFY(gui->controller->setType({EKind::Port, ticks, {}, {}}));
        QVERIFY(gui->document.orphans().isEmpty());
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
        QCOMPARE(gui->document.corrections().size(), 1);
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->document.accepted().nodes.node(recorder) == nullptr, done);
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
        QVERIFY(gui->document.corrections().isEmpty());
        QVERIFY(gui->document.accepted().nodes.node(recorder));
        gui->document.undoStack()->undo(); // the restore
        QVERIFY(!gui->document.accepted().nodes.node(recorder));

        const QString odom = gui->portId(QStringLiteral("Recorder"), "odom");
        QVERIFY(gui->controller->remove(
            {EKind::Port, gui->portId("SafetyMonitor", "reset_estop"), {}, {}}));
        QCOMPARE(gui->document.corrections().last().target,
                 QStringLiteral("port:cart_base|cart_base.safety.SafetyMonitor|service_server|"
                                "reset_estop"));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portNames(QStringLiteral("SafetyMonitor")).contains("reset_estop"),
                     true); // still listed, struck out
            QCOMPARE(gui->portId("SafetyMonitor", "reset_estop").isEmpty(), done);
        });
        Q_UNUSED(odom);

        const QString recorderInstance = gui->instanceId(QStringLiteral("recorder"));
        QVERIFY(gui->controller->remove({EKind::Instance, recorderInstance, {}, {}}));
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
            for (const Composite &c : gui->document.accepted().architecture.composites)
                for (const RosNodePart &p : c.parts)
                    if (p.instanceId == odometry)
                        return std::any_of(
                            p.ports.cbegin(), p.ports.cend(),
                            [&](const PartPort &pp) { return pp.id == odomPort.section(u'/', 1); });
            return false;
        };
        QVERIFY(connected());
        QVERIFY(gui->controller->remove({EKind::Connection, odometry, odomPort, {}}));
        QVERIFY(!gui->document.corrections().last().port.isEmpty());
        roundTrip(*gui, [&](bool done) { QCOMPARE(connected(), !done); });
        QVERIFY(gui->document.orphans().isEmpty());
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
        QVERIFY(gui->controller->addPort({EKind::Class, safety, {}, {}}));
        roundTrip(*gui, [&](bool done) {
            QCOMPARE(gui->portNames(QStringLiteral("SafetyMonitor")).contains("sensors/bumper"),
                     done);
        });
        const QString added = gui->portId(QStringLiteral("SafetyMonitor"), "sensors/bumper");
        QCOMPARE(gui->nodeModel.portIndex(added.section(u'/', 0, 0), added.section(u'/', 1))
                     .data(AtomicNodeModel::ProvenanceRole),
                 QVariant(QStringLiteral("corrected")));
        QCOMPARE(gui->controller->describe({EKind::Port, added, {}, {}}).provenance,
                 QStringLiteral("corrected by c1"));

        // Add Part on a launch file: pick a class among the workspace's
        const QString cart = gui->launchFileId(QStringLiteral("cart.launch.py"));
        gui->answer = [](CorrectionDialog &d) {
            if (!d.setChoice(QStringLiteral("class:cart_base|cart_base.safety.SafetyMonitor")))
                return false;
            d.setName(QStringLiteral("watchdog"));
            return true;
        };
        QVERIFY(gui->controller->addPart({EKind::LaunchFile, cart, {}, {}}));
        QCOMPARE(gui->document.corrections().last().target,
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
        QVERIFY(gui->controller->addConnection({EKind::Instance, odometry, {}, {}}));
        QCOMPARE(gui->document.corrections().last().newValue, QStringLiteral("/cart/heartbeat"));
        roundTrip(*gui, [&](bool done) {
            bool found = false;
            for (const Composite &c : gui->document.accepted().architecture.composites)
                for (const RosNodePart &p : c.parts)
                    for (const PartPort &pp : p.ports)
                        found = found || (p.instanceId == odometry &&
                                          pp.name == QLatin1String("/cart/heartbeat"));
            QCOMPARE(found, done);
        });
        QVERIFY(gui->document.orphans().isEmpty());
    }

    void renameTopicGroupAndReview()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("/emergency_stop"));
            return true;
        };
        QVERIFY(gui->controller->rename({EKind::Channel, QStringLiteral("topic:/estop"), {}, {}}));
        const auto hasChannel = [&](const QString &name) {
            for (const Composite &c : gui->document.accepted().architecture.composites)
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
        QVERIFY(gui->controller->rename(
            {EKind::Channel, QStringLiteral("topic:/emergency_stop"), {}, {}}));
        QCOMPARE(gui->document.corrections().last().target, QStringLiteral("topic:/estop"));
        QVERIFY(hasChannel(QStringLiteral("/e_stop")));

        // group two parts of the root
        const QString root = gui->launchFileId(QStringLiteral("cart.launch.py"));
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("Motion safety"));
            return true;
        };
        QVERIFY(gui->controller->group(
            {gui->instanceId("odometry"), gui->instanceId("safety_monitor")}, root));
        roundTrip(*gui, [&](bool done) {
            bool grouped = false;
            for (const Composite &c : gui->document.accepted().architecture.composites)
                for (const RosNodePart &p : c.parts)
                    grouped = grouped || p.subsystem == QLatin1String("Motion safety");
            QCOMPARE(grouped, done);
        });

        // review: at once, a ✓ in the views; again removes the mark
        const QString odometryNode = gui->classId(QStringLiteral("OdometryNode"));
        const int before = int(gui->document.corrections().size());
        QVERIFY(gui->controller->toggleReviewed({EKind::Class, odometryNode, {}, {}}));
        QCOMPARE(gui->asked.size(), 3); // no dialog for a review
        roundTrip(*gui, [&](bool done) {
            const QModelIndex row = gui->nodeModel.nodeIndex(odometryNode);
            QCOMPARE(row.data(AtomicNodeModel::ReviewedRole).toBool(), done);
            QCOMPARE(row.data().toString(),
                     done ? QStringLiteral("OdometryNode \u2713") : QStringLiteral("OdometryNode"));
        });
        QVERIFY(gui->controller->toggleReviewed({EKind::Class, odometryNode, {}, {}}));
        QCOMPARE(int(gui->document.corrections().size()), before);
        const QString odometry = gui->instanceId(QStringLiteral("odometry"));
        QVERIFY(gui->controller->toggleReviewed({EKind::Instance, odometry, {}, {}}));
        QVERIFY(gui->launchModel.nodeIndex(odometry).data(LaunchTreeModel::ReviewedRole).toBool());
        QVERIFY(gui->controller->describe({EKind::Instance, odometry, {}, {}}).reviewed);
    }

    void cancelledDialogChangesNothing()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("x"));
            return false;
        };
        QVERIFY(!gui->controller->rename(
            {EKind::Instance, gui->instanceId(QStringLiteral("odometry")), {}, {}}));
        QVERIFY(gui->document.corrections().isEmpty());
        QCOMPARE(gui->document.undoStack()->count(), 0);
    }

    void inspectorShowsTheSelection()
    {
        auto gui = open();
        const QString odometry = gui->instanceId(QStringLiteral("odometry"));
        gui->launchPanel.selectSourceIndex(gui->launchModel.nodeIndex(odometry));
        QCOMPARE(gui->controller->current().kind, EKind::Instance);
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("kind")), QStringLiteral("Node instance"));
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("name")), QStringLiteral("odometry"));
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("type")), QStringLiteral("OdometryNode"));
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("key")),
                 QStringLiteral("instance:src/cart_base/launch/cart.launch.py|odometry"));
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("provenance")),
                 QStringLiteral("recovered by analysis"));
        QStringList buttons;
        for (QAction *a : gui->inspector.actions())
            buttons.append(a->text());
        QVERIFY2(buttons.contains(QStringLiteral("Mark Re&viewed")), qPrintable(buttons.join('|')));
        // a button makes the correction; the inspector follows
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("odom_node"));
            return true;
        };
        gui->inspector.actions().first()->trigger(); // Rename…
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("name")), QStringLiteral("odom_node"));
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("provenance")),
                 QStringLiteral("corrected by c1"));
        QVERIFY(gui->inspector.info().corrections.contains(
            QStringLiteral("odometry \u2192 odom_node")));
    }

    void correctionsPanelListsAndReverts()
    {
        auto gui = open();
        QAbstractItemModelTester tester(&gui->correctionModel,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QAbstractItemModelTester nodes(&gui->nodeModel,
                                       QAbstractItemModelTester::FailureReportingMode::QtTest);
        QAbstractItemModelTester launch(&gui->launchModel,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(gui->correctionModel.rowCount(), 0);
        gui->answer = [](CorrectionDialog &d) {
            if (d.fields() & CorrectionDialog::Name)
                d.setName(QStringLiteral("laser_safety"));
            if (d.fields() & CorrectionDialog::Choice)
                d.setChoice(QStringLiteral("class:cart_base|cart_base.bumper.BumperNode"));
            d.setReason(QStringLiteral("because"));
            return true;
        };
        const QString safety = gui->instanceId(QStringLiteral("safety_monitor"));
        QVERIFY(gui->controller->rename({EKind::Instance, safety, {}, {}}));
        QVERIFY(gui->controller->addPart(
            {EKind::LaunchFile, gui->launchFileId(QStringLiteral("cart.launch.py")), {}, {}}));
        QVERIFY(gui->controller->remove(
            {EKind::Instance, gui->instanceId(QStringLiteral("recorder")), {}, {}}));
        QCOMPARE(gui->correctionModel.rowCount(), 3);
        const auto cell = [&](int row, int column) {
            return gui->correctionModel.index(row, column).data().toString();
        };
        QCOMPARE(cell(0, CorrectionModel::KindColumn), QStringLiteral("c1  Rename"));
        QCOMPARE(cell(0, CorrectionModel::TargetColumn),
                 QStringLiteral("instance:src/cart_base/launch/cart.launch.py|safety_monitor"));
        QCOMPARE(cell(0, CorrectionModel::ChangeColumn),
                 QStringLiteral("safety_monitor \u2192 laser_safety"));
        QCOMPARE(cell(0, CorrectionModel::ReasonColumn), QStringLiteral("because"));
        QCOMPARE(cell(0, CorrectionModel::AuthorColumn), QStringLiteral("tester"));
        QCOMPARE(cell(0, CorrectionModel::StatusColumn), QStringLiteral("applied"));
        QCOMPARE(cell(1, CorrectionModel::KindColumn), QStringLiteral("c2  Add part"));
        QCOMPARE(cell(2, CorrectionModel::KindColumn), QStringLiteral("c3  Remove"));

        // selecting one selects its element
        QVERIFY(gui->correctionPanel.selectCorrection(QStringLiteral("c1")));
        QCOMPARE(gui->launchPanel.currentSourceIndex(), gui->launchModel.nodeIndex(safety));
        QCOMPARE(gui->controller->current().id, safety);

        // Remove (Delete) reverts it, undoably
        gui->correctionPanel.removeAction()->trigger();
        QCOMPARE(gui->correctionModel.rowCount(), 2);
        QVERIFY(gui->instance(QStringLiteral("safety_monitor")));
        QCOMPARE(gui->launchModel.nodeIndex(safety).data().toString(),
                 QStringLiteral("safety_monitor"));
        gui->document.undoStack()->undo();
        QCOMPARE(gui->correctionModel.rowCount(), 3);
        QCOMPARE(cell(0, CorrectionModel::KindColumn), QStringLiteral("c1  Rename"));
        QVERIFY(gui->instance(QStringLiteral("laser_safety")));

        // several at once are one step
        gui->correctionPanel.tableView()->selectAll();
        gui->correctionPanel.removeAction()->trigger();
        QCOMPARE(gui->correctionModel.rowCount(), 0);
        QCOMPARE(gui->document.accepted(), gui->document.accepted()); // computed
        QVERIFY(gui->instance(QStringLiteral("recorder")));
        gui->document.undoStack()->undo();
        QCOMPARE(gui->correctionModel.rowCount(), 3);
    }

    void rerunKeepsCorrections()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("safety"));
            return true;
        };
        QVERIFY(gui->controller->rename(
            {EKind::Instance, gui->instanceId(QStringLiteral("safety_monitor")), {}, {}}));
        QVERIFY(gui->controller->toggleReviewed(
            {EKind::Class, gui->classId(QStringLiteral("BumperNode")), {}, {}}));
        // F5: a fresh recovery of the same workspace
        gui->document.setRecovery(recover(m_ws));
        QCOMPARE(gui->document.corrections().size(), 2);
        QVERIFY(gui->document.orphans().isEmpty());
        QVERIFY(gui->instance(QStringLiteral("safety")));
        const QString id = gui->instanceId(QStringLiteral("safety"));
        QCOMPARE(gui->launchModel.nodeIndex(id).data().toString(), QStringLiteral("safety"));
        QVERIFY(gui->nodeModel.nodeIndex(gui->classId(QStringLiteral("BumperNode")))
                    .data(AtomicNodeModel::ReviewedRole)
                    .toBool());
        QCOMPARE(gui->correctionModel.rowCount(), 2);
    }

    void orphanIsListedAndRetargeted()
    {
        auto gui = open();
        Correction c;
        c.kind = Correction::Kind::Rename;
        c.target = QStringLiteral("instance:src/cart_base/launch/cart.launch.py|gone");
        c.oldValue = QStringLiteral("gone");
        c.newValue = QStringLiteral("renamed");
        c.reason = QStringLiteral("kept");
        QCOMPARE(gui->document.addCorrection(c), QStringLiteral("c1"));
        QCOMPARE(gui->document.orphans().size(), 1);
        QVERIFY(gui->correctionModel.index(0, 0).data(CorrectionModel::OrphanedRole).toBool());
        QVERIFY(gui->correctionModel.index(0, CorrectionModel::StatusColumn)
                    .data()
                    .toString()
                    .startsWith(QStringLiteral("orphaned: nothing in this recovery has the key")));
        QVERIFY(gui->correctionModel.index(0, 0).data(Qt::ForegroundRole).isValid());
        gui->correctionPanel.selectCorrection(QStringLiteral("c1"));
        QVERIFY(gui->correctionPanel.retargetAction()->isEnabled());

        QStringList offered;
        gui->answer = [&](CorrectionDialog &d) {
            for (const NodeInstance &n : gui->document.accepted().launch.nodes)
                if (d.setChoice(QStringLiteral("instance:src/cart_base/launch/cart.launch.py|%1")
                                    .arg(n.nodeName)))
                    offered.append(n.nodeName);
            // only instances: a class key is not offered
            if (d.setChoice(QStringLiteral("class:cart_base|cart_base.bumper.BumperNode")))
                return false;
            return d.setChoice(
                QStringLiteral("instance:src/cart_base/launch/cart.launch.py|recorder"));
        };
        gui->correctionPanel.retargetAction()->trigger();
        QVERIFY2(offered.contains(QStringLiteral("odometry")), qPrintable(offered.join(u',')));
        QCOMPARE(gui->document.corrections().size(), 1);
        const Correction &now = gui->document.corrections().first();
        QCOMPARE(now.id, QStringLiteral("c1"));
        QCOMPARE(now.target,
                 QStringLiteral("instance:src/cart_base/launch/cart.launch.py|recorder"));
        QCOMPARE(now.reason, QStringLiteral("kept"));
        QVERIFY(gui->document.orphans().isEmpty());
        QVERIFY(gui->instance(QStringLiteral("renamed")));
        QVERIFY(!gui->correctionModel.index(0, 0).data(CorrectionModel::OrphanedRole).toBool());
        // one undo step puts the orphan back
        gui->document.undoStack()->undo();
        QCOMPARE(gui->document.corrections().first().target, c.target);
        QCOMPARE(gui->document.orphans().size(), 1);
        QVERIFY(!gui->instance(QStringLiteral("renamed")));
    }

    void projectFixtureShowsProvenanceEverywhere()
    {
        // the fixture's project: one correction of each kind
        QTemporaryDir dir;
        const QString ws = dir.filePath(QStringLiteral("ws"));
        QVERIFY(copyTree(QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/ws"), ws));
        QVERIFY(QFile::copy(
            QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/rosarch.project.json"),
            QDir(ws).filePath(QStringLiteral("rosarch.project.json"))));
        Gui gui;
        gui.document.setRecovery(recover(ws));
        QCOMPARE(gui.document.corrections().size(), 13);
        QAbstractItemModelTester nodes(&gui.nodeModel,
                                       QAbstractItemModelTester::FailureReportingMode::QtTest);
        QAbstractItemModelTester launch(&gui.launchModel,
                                        QAbstractItemModelTester::FailureReportingMode::QtTest);
        QCOMPARE(gui.correctionModel.rowCount(), 13);
        QVERIFY(gui.launchNodes().contains(QStringLiteral("watchdog")));
        QVERIFY(gui.launchNodes().contains(QStringLiteral("safety")));
        QVERIFY(gui.launchNodes().contains(QStringLiteral("recorder"))); // struck out
        QVERIFY(gui.portNames(QStringLiteral("SafetyMonitor")).contains("sensors/bumper"));
        QVERIFY(gui.portNames(QStringLiteral("OdometryNode")).contains("wheel/ticks"));
        const QModelIndex odometry = gui.nodeModel.nodeIndex(gui.classId("OdometryNode"));
        QCOMPARE(odometry.data().toString(), QStringLiteral("OdometryNode \u2713"));
        QVERIFY(
            odometry.data(Qt::ToolTipRole).toString().contains(QStringLiteral("Reviewed by c11")));
        const QString ticks = gui.portId(QStringLiteral("OdometryNode"), "wheel/ticks");
        const QModelIndex ticksRow =
            gui.nodeModel.portIndex(ticks.section(u'/', 0, 0), ticks.section(u'/', 1));
        QVERIFY(ticksRow.data(Qt::ForegroundRole).isValid());
        QVERIFY(
            ticksRow.data(Qt::ToolTipRole).toString().contains(QStringLiteral("Corrected by c2")));
        QCOMPARE(gui.controller->describe({EKind::Port, ticks, {}, {}}).provenance,
                 QStringLiteral("corrected by c2"));
        // and the diagram draws the marks
        gui.diagramPanel.setArchitecture(gui.document.accepted().architecture);
        QSignalSpy laidOut(&gui.diagramPanel, &DiagramPanel::layoutFinished);
        QVERIFY(laidOut.count() > 0 || laidOut.wait(20000));
        int corrected = 0;
        int reviewed = 0;
        for (const Composite &c : gui.diagramPanel.architecture().composites)
            for (const RosNodePart &p : c.parts) {
                corrected += p.marks.provenance == Provenance::Corrected ? 1 : 0;
                reviewed += p.marks.reviewed ? 1 : 0;
            }
        QVERIFY(corrected >= 2); // safety (renamed), watchdog (added)
        Q_UNUSED(reviewed);
    }
};

QTEST_MAIN(TestCorrections)
#include "tst_corrections.moc"
