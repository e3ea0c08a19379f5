// Corrections in the GUI's panels: the inspector, the Corrections panel, re-running
// the stages, orphans and re-targeting, and a project's corrections shown everywhere.
#include "project/stablekeys.h"
#include "support/acceptedwait.h"
#include "support/correctiongui.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test;
using Element = CorrectionController::Element;
using EKind = CorrectionController::Element::Kind;

class TestCorrectionPanels : public CorrectionTestBase
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase() { setUpFixture(); }
    void init() { forgetProjects(); }

    void inspectorShowsTheSelection()
    {
        auto gui = open();
        const QString odometry = gui->instanceId(QStringLiteral("odometry"));
        gui->launchPanel.selectSourceIndex(gui->launchModel.nodeIndex(odometry));
        QCOMPARE(gui->controller->presenter()->current().kind, EKind::Instance);
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
        gui->inspector.actions().first()->trigger();   // Rename…
        QVERIFY(test::acceptedSettled(gui->document)); // the inspector shows the model as accepted
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("name")), QStringLiteral("odom_node"));
        QCOMPARE(gui->inspector.fieldText(QStringLiteral("provenance")),
                 QStringLiteral("corrected by c1"));
        QVERIFY(gui->inspector.info().corrections.contains(
            QStringLiteral("odometry \u2192 odom_node")));
    }

    void inspectorDoesNotWaitForTheKeysOfALargeModel()
    {
        // As large as a 3,000-package workspace: its stable keys are made on a thread of their
        // own, and the inspector shows an element's key once they are there.
        const auto large = [this](const QString &package) {
            Recovery r = recover(m_ws);
            const AtomicNode like = r.nodes.nodes.first();
            for (int i = 0; i < 4000; ++i) {
                AtomicNode n = like;
                n.id = QStringLiteral("arc_x%1").arg(i);
                n.packageName = package + QString::number(i);
                r.nodes.nodes.append(n);
            }
            return r;
        };
        const Recovery first = large(QStringLiteral("first_"));
        const Recovery second = large(QStringLiteral("second_"));
        const QString id = QStringLiteral("arc_x3999");
        Gui gui;
        QSignalSpy made(gui.document.session(), &ProjectSession::keysMade);
        gui.document.setRecovery(first);
        gui.document.setRecovery(second); // while the first one's keys may still be made
        gui.controller->presenter()->setCurrent({EKind::Class, id, {}, {}});
        const QString expected = StableKeys(second).keyOf(id);
        QVERIFY(expected.startsWith(QStringLiteral("class:second_3999|")));
        const QString shown = gui.inspector.fieldText(QStringLiteral("key"));
        QVERIFY2(shown == expected || shown == QStringLiteral("(being worked out\u2026)"),
                 qPrintable(shown));
        QTRY_COMPARE(gui.inspector.fieldText(QStringLiteral("key")), expected);
        QVERIFY(gui.document.session()->keysReady());
        QCOMPARE(gui.document.session()->keyOf(id), expected); // not the first model's key
        QCOMPARE(gui.document.session()->keyOf(QStringLiteral("arc_x0")),
                 StableKeys(second).keyOf("arc_x0"));
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
        QVERIFY(gui->controller->editor()->rename({EKind::Instance, safety, {}, {}}));
        QVERIFY(gui->controller->editor()->addPart(
            {EKind::LaunchFile, gui->launchFileId(QStringLiteral("cart.launch.py")), {}, {}}));
        QVERIFY(gui->controller->editor()->remove(
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
        QCOMPARE(gui->controller->presenter()->current().id, safety);

        // Remove (Delete) reverts it, undoably
        gui->correctionPanel.removeAction()->trigger();
        QCOMPARE(gui->correctionModel.rowCount(), 2);
        QVERIFY(gui->instance(QStringLiteral("safety_monitor")));
        QCOMPARE(gui->launchModel.nodeIndex(safety).data().toString(),
                 QStringLiteral("safety_monitor"));
        gui->document.undoStack()->undo();
        QVERIFY(test::acceptedSettled(gui->document));
        QCOMPARE(gui->correctionModel.rowCount(), 3);
        QCOMPARE(cell(0, CorrectionModel::KindColumn), QStringLiteral("c1  Rename"));
        QVERIFY(gui->instance(QStringLiteral("laser_safety")));

        // several at once are one step
        gui->correctionPanel.tableView()->selectAll();
        gui->correctionPanel.removeAction()->trigger();
        QCOMPARE(gui->correctionModel.rowCount(), 0);
        QCOMPARE(test::acceptedNow(gui->document), test::acceptedNow(gui->document)); // computed
        QVERIFY(gui->instance(QStringLiteral("recorder")));
        gui->document.undoStack()->undo();
        QVERIFY(test::acceptedSettled(gui->document));
        QCOMPARE(gui->correctionModel.rowCount(), 3);
    }

    void rerunKeepsCorrections()
    {
        auto gui = open();
        gui->answer = [](CorrectionDialog &d) {
            d.setName(QStringLiteral("safety"));
            return true;
        };
        QVERIFY(gui->controller->editor()->rename(
            {EKind::Instance, gui->instanceId(QStringLiteral("safety_monitor")), {}, {}}));
        QVERIFY(gui->controller->editor()->toggleReviewed(
            {EKind::Class, gui->classId(QStringLiteral("BumperNode")), {}, {}}));
        // F5: a fresh recovery of the same workspace
        gui->document.setRecovery(recover(m_ws));
        QCOMPARE(gui->document.session()->corrections().size(), 2);
        QVERIFY(gui->document.session()->orphans().isEmpty());
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
        QCOMPARE(gui->document.session()->addCorrection(c), QStringLiteral("c1"));
        QVERIFY(test::acceptedSettled(gui->document)); // orphans are found applying the project
        QCOMPARE(gui->document.session()->orphans().size(), 1);
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
            for (const NodeInstance &n : test::acceptedNow(gui->document).launch.nodes)
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
        QVERIFY(test::acceptedSettled(gui->document));
        QVERIFY2(offered.contains(QStringLiteral("odometry")), qPrintable(offered.join(u',')));
        QCOMPARE(gui->document.session()->corrections().size(), 1);
        const Correction &now = gui->document.session()->corrections().first();
        QCOMPARE(now.id, QStringLiteral("c1"));
        QCOMPARE(now.target,
                 QStringLiteral("instance:src/cart_base/launch/cart.launch.py|recorder"));
        QCOMPARE(now.reason, QStringLiteral("kept"));
        QVERIFY(gui->document.session()->orphans().isEmpty());
        QVERIFY(gui->instance(QStringLiteral("renamed")));
        QVERIFY(!gui->correctionModel.index(0, 0).data(CorrectionModel::OrphanedRole).toBool());
        // one undo step puts the orphan back
        gui->document.undoStack()->undo();
        QVERIFY(test::acceptedSettled(gui->document));
        QCOMPARE(gui->document.session()->corrections().first().target, c.target);
        QCOMPARE(gui->document.session()->orphans().size(), 1);
        QVERIFY(!gui->instance(QStringLiteral("renamed")));
    }

    void projectFixtureShowsProvenanceEverywhere()
    {
        // the fixture's project: one correction of each kind
        QTemporaryDir dir;
        const QString ws = dir.filePath(QStringLiteral("ws"));
        QVERIFY(copyFixture(QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/ws"), ws));
        QVERIFY(QFile::copy(
            QStringLiteral(ROSARCH_TEST_DATA "/project_corrections/rosarch.project.json"),
            QDir(ws).filePath(QStringLiteral("rosarch.project.json"))));
        Gui gui;
        gui.document.setRecovery(recover(ws));
        QCOMPARE(gui.document.session()->corrections().size(), 13);
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
        QCOMPARE(gui.controller->presenter()->describe({EKind::Port, ticks, {}, {}}).provenance,
                 QStringLiteral("corrected by c2"));
        // and the diagram draws the marks
        gui.diagramPanel.setArchitecture(test::acceptedNow(gui.document).architecture);
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

QTEST_MAIN(TestCorrectionPanels)
#include "tst_correctionpanels.moc"
