// Who talks on a topic, service or action, on tests/data/compose_system inside the main
// window: a click on a channel, a port or an edge lists the talkers of that resolved name
// across the shown composite and its includes; choosing a talker selects its instance in the
// launch tree, the diagram, the node list and the source; a click on an edge selects its
// part's instance everywhere, as a click on the part does.
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "support/acceptedwait.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagramedgeitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"
#include "widgets/talkerspanel.h"

#include <QDockWidget>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>

using namespace rosarch;

namespace {

/// The talkers panel as text: one "header" line per name, one "node | role | port | class"
/// line per node instance under it, and one "| role | port |" line per port under an instance
/// with more than one.
QStringList rows(const TalkersPanel *panel)
{
    QStringList out;
    const QTreeWidget *tree = panel->tree();
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem *head = tree->topLevelItem(i);
        out << head->text(0);
        for (int j = 0; j < head->childCount(); ++j) {
            const QTreeWidgetItem *r = head->child(j);
            out << QStringLiteral("  %1 | %2 | %3 | %4")
                       .arg(r->text(0), r->text(1), r->text(2), r->text(3));
            for (int k = 0; r->childCount() > 1 && k < r->childCount(); ++k)
                out << QStringLiteral("    | %1 | %2 |")
                           .arg(r->child(k)->text(1), r->child(k)->text(2));
        }
    }
    return out;
}

QTreeWidgetItem *row(const TalkersPanel *panel, const QString &nodeName)
{
    const QTreeWidget *tree = panel->tree();
    for (int i = 0; i < tree->topLevelItemCount(); ++i)
        for (int j = 0; j < tree->topLevelItem(i)->childCount(); ++j)
            if (tree->topLevelItem(i)->child(j)->text(0) == nodeName)
                return tree->topLevelItem(i)->child(j);
    return nullptr;
}

} // namespace

class TestTalkers : public QObject
{
    Q_OBJECT

    MainWindow *m_window = nullptr;

    DiagramPanel *diagram() const { return test::child<DiagramPanel>(*m_window); }
    TalkersPanel *talkers() const { return test::child<TalkersPanel>(*m_window); }
    Document *doc() const { return test::child<Document>(*m_window); }

    bool waitForLayout()
    {
        if (!diagram()->isLayingOut())
            return true;
        QSignalSpy done(diagram(), &DiagramPanel::layoutFinished);
        return done.wait(30000);
    }

    bool showComposite(const QString &id)
    {
        diagram()->showComposite(id);
        return waitForLayout() && diagram()->currentComposite() == id;
    }

    /// Clicks the view where `key` is drawn (at `scenePos` when given).
    bool click(const QString &key, QPointF scenePos = {})
    {
        DiagramItem *item = diagram()->scene()->item(key);
        if (!item)
            return false;
        if (scenePos.isNull())
            scenePos = item->sceneBoundingRect().center();
        DiagramView *view = diagram()->view();
        view->centerOn(scenePos);
        if (diagram()->scene()->keyAt(scenePos) != key)
            return false; // something else is drawn there
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(scenePos));
        return true;
    }

    QString launchSelection() const
    {
        return test::child<LaunchTreePanel>(*m_window)
            ->currentSourceIndex()
            .data(LaunchTreeModel::InstanceIdRole)
            .toString();
    }

    QString classIdOf(const QString &className) const
    {
        for (const AtomicNode &n : doc()->atomicNodes().nodes)
            if (n.className == className)
                return n.id;
        return {};
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        m_window = new MainWindow;
        m_window->resize(1600, 900);
        m_window->show();
        QSignalSpy finished(test::child<StageRunner>(*m_window), &StageRunner::stageFinished);
        m_window->openWorkspace(test::dataDir(QStringLiteral("compose_system/ws")));
        QVERIFY(finished.wait(60000));
        QVERIFY(waitForLayout());
        QCOMPARE(diagram()->currentComposite(), QStringLiteral("lf1"));
        QVERIFY(!test::child<QDockWidget>(*m_window, QStringLiteral("talkersDock"))
                     ->isVisible()); // nothing clicked yet
    }

    void cleanupTestCase() { delete m_window; }

    void channelClickListsPublishersAndSubscribers()
    {
        QVERIFY(showComposite(QStringLiteral("lf1")));
        QVERIFY(click(QStringLiteral("channel:q_detections")));
        QVERIFY(test::child<QDockWidget>(*m_window, QStringLiteral("talkersDock"))->isVisible());
        // The publisher is inside the front include of vision; the rear one's is remapped
        // to /rear/detections and does not talk here.
        QCOMPARE(rows(talkers()),
                 (QStringList{
                     QStringLiteral("topic /detections · vision_msgs/msg/Detection2DArray · "
                                    "1 publisher, 2 subscribers"),
                     QStringLiteral("  /front/detector | publisher | p1  /detections | Detector"),
                     QStringLiteral("  /backup_planner | subscriber | s1  /detections | Planner"),
                     QStringLiteral("  /planner | subscriber | s1  /detections | Planner"),
                 }));
        QCOMPARE(talkers()->summary(), QStringLiteral("Talkers on topic /detections in system"));
        test::saveScreenshot(*m_window, QStringLiteral("talkers-topic.png"));
    }

    void talkersFollowACorrection()
    {
        QVERIFY(showComposite(QStringLiteral("lf1")));
        QVERIFY(click(QStringLiteral("channel:q_detections")));
        QVERIFY(row(talkers(), QStringLiteral("/backup_planner")));
        // A person removes the backup planner: the talkers shown follow the corrected model.
        QString backup;
        for (const NodeInstance &n : doc()->launchDependencies().nodes)
            if (n.nodeName == QLatin1String("backup_planner"))
                backup = n.id;
        QVERIFY(!backup.isEmpty());
        Correction remove;
        remove.kind = Correction::Kind::Remove;
        remove.target = doc()->session()->keyOf(backup);
        const QString id = doc()->session()->addCorrection(remove);
        QVERIFY(!id.isEmpty());
        QVERIFY(test::acceptedSettled(*doc()));
        QVERIFY(!row(talkers(), QStringLiteral("/backup_planner")));
        QVERIFY(row(talkers(), QStringLiteral("/planner")));
        doc()->undoStack()->undo(); // and back
        QVERIFY(test::acceptedSettled(*doc()));
        QVERIFY(row(talkers(), QStringLiteral("/backup_planner")));
    }

    void actionClickListsServersAndClients()
    {
        QVERIFY(showComposite(QStringLiteral("lf1")));
        QVERIFY(click(QStringLiteral("channel:a_navigate")));
        // The counts are of active node instances: sim_commander (inactive) is listed apart.
        QCOMPARE(rows(talkers()),
                 (QStringList{
                     QStringLiteral("action /navigate · planning_interfaces/action/Navigate · "
                                    "2 servers, 1 client, 1 inactive"),
                     QStringLiteral("  /backup_planner | action server | pa1  navigate | Planner"),
                     QStringLiteral("  /planner | action server | pa1  navigate | Planner"),
                     QStringLiteral("  /commander | action client | ra1  navigate | Commander"),
                     QStringLiteral("  /sim_commander | action client | ra1  navigate | Commander"),
                 }));
        // sim_commander's launch condition is false: listed, but greyed and said so.
        QTreeWidgetItem *sim = row(talkers(), QStringLiteral("/sim_commander"));
        QVERIFY(sim);
        QVERIFY(sim->toolTip(0).contains(QLatin1String("Inactive")));
        QVERIFY(!row(talkers(), QStringLiteral("/commander"))
                     ->toolTip(0)
                     .contains(QLatin1String("Inactive")));
    }

    void choosingATalkerSelectsItEverywhere()
    {
        QVERIFY(showComposite(QStringLiteral("lf1")));
        QVERIFY(click(QStringLiteral("channel:q_detections")));
        const QStringList before = rows(talkers());
        QTreeWidgetItem *detector = row(talkers(), QStringLiteral("/front/detector"));
        QVERIFY(detector);
        talkers()->tree()->setCurrentItem(detector);
        QVERIFY(waitForLayout());
        // Launch tree: the instance; diagram: its composite (front vision) with its part;
        // node list: its class's port; source: the port's creation.
        QCOMPARE(launchSelection(), QStringLiteral("n4"));
        QCOMPARE(diagram()->currentComposite(), QStringLiteral("lf2"));
        QVERIFY(diagram()->scene()->item(QStringLiteral("part:part3"))->isSelected());
        const QModelIndex port = test::child<AtomicNodePanel>(*m_window)->currentSourceIndex();
        QCOMPARE(port.data(AtomicNodeModel::NodeIdRole).toString(),
                 classIdOf(QStringLiteral("Detector")));
        QCOMPARE(port.data(AtomicNodeModel::PortIdRole).toString(), QStringLiteral("p1"));
        QCOMPARE(test::child<SourceView>(*m_window)->currentFile(),
                 QStringLiteral("src/vision/src/detector.cpp"));
        // The list stays while the user walks it.
        QCOMPARE(rows(talkers()), before);

        // The next talker goes back to the root composite.
        talkers()->tree()->setCurrentItem(row(talkers(), QStringLiteral("/planner")));
        QVERIFY(waitForLayout());
        QCOMPARE(launchSelection(), QStringLiteral("n9"));
        QCOMPARE(diagram()->currentComposite(), QStringLiteral("lf1"));
        QVERIFY(diagram()->scene()->item(QStringLiteral("part:part3"))->isSelected());
        QCOMPARE(test::child<AtomicNodePanel>(*m_window)
                     ->currentSourceIndex()
                     .data(AtomicNodeModel::PortIdRole)
                     .toString(),
                 QStringLiteral("s1"));
        QCOMPARE(test::child<SourceView>(*m_window)->currentFile(),
                 QStringLiteral("src/planning/planning/planner.py"));
        QCOMPARE(rows(talkers()), before);
    }

    void nodeListPortListsTheNamesOfItsInstances()
    {
        QVERIFY(showComposite(QStringLiteral("lf1")));
        const QString camera = classIdOf(QStringLiteral("Camera"));
        test::child<AtomicNodePanel>(*m_window)->selectSourceIndex(
            test::child<AtomicNodeModel>(*m_window)->portIndex(camera, QStringLiteral("s1")));
        // Camera starts twice below system, so its trigger port has two names.
        QCOMPARE(rows(talkers()),
                 (QStringList{
                     QStringLiteral("topic /front/trigger · std_msgs/msg/Empty · "
                                    "2 publishers, 1 subscriber"),
                     QStringLiteral("  /backup_planner | publisher | p2  front/trigger | Planner"),
                     QStringLiteral("  /planner | publisher | p2  front/trigger | Planner"),
                     QStringLiteral("  /front/front_camera | subscriber | s1  trigger | Camera"),
                     QStringLiteral("topic /rear/trigger · std_msgs/msg/Empty · "
                                    "0 publishers, 1 subscriber"),
                     QStringLiteral("  /rear/rear_camera | subscriber | s1  trigger | Camera"),
                 }));
        QCOMPARE(talkers()->summary(), QStringLiteral("Talkers on port s1 of Camera in system"));
    }

    void namesLeavingTheCompositeSaySo()
    {
        QVERIFY(showComposite(QStringLiteral("lf2")));
        // What a click on front detector's /detections port emits (a port is drawn by its part).
        Q_EMIT diagram()->scene()->elementClicked(QStringLiteral("port:part3/p1"));
        QCOMPARE(rows(talkers()),
                 (QStringList{
                     QStringLiteral("topic /detections · vision_msgs/msg/Detection2DArray · "
                                    "1 publisher, 0 subscribers"),
                     QStringLiteral("  /front/detector | publisher | p1  /detections | Detector"),
                 }));
        QVERIFY2(talkers()->summary().contains(
                     QLatin1String("/detections leaves vision through its boundary")),
                 qPrintable(talkers()->summary()));
    }

    void edgeClickSelectsItsInstanceEverywhere()
    {
        QVERIFY(showComposite(QStringLiteral("lf1")));
        // Select something else first, so that each view has to move.
        test::child<LaunchTreePanel>(*m_window)->selectSourceIndex(
            test::child<LaunchTreeModel>(*m_window)->nodeIndex(QStringLiteral("n11")));
        QVERIFY(waitForLayout());
        const Composite *c = doc()->architecture().composite(QStringLiteral("lf1"));
        int index = -1;
        for (int i = 0; i < c->connections.size(); ++i)
            if (c->connections[i].partId == QLatin1String("part3") &&
                c->connections[i].targetId == QLatin1String("q_detections"))
                index = i;
        QVERIFY(index >= 0);
        const QString key = QStringLiteral("connection:%1").arg(index);
        auto *edge = dynamic_cast<DiagramEdgeItem *>(diagram()->scene()->item(key));
        QVERIFY(edge);
        QVERIFY(click(key, edge->mapToScene(edge->path().pointAtPercent(0.5))));
        // planner (n9, part3) everywhere: the launch tree, the node list's class, the part
        // next to the edge in the diagram; the source shows the subscription in code.
        QCOMPARE(launchSelection(), QStringLiteral("n9"));
        QCOMPARE(test::child<AtomicNodePanel>(*m_window)
                     ->currentSourceIndex()
                     .data(AtomicNodeModel::NodeIdRole)
                     .toString(),
                 classIdOf(QStringLiteral("Planner")));
        QVERIFY(diagram()->scene()->item(QStringLiteral("part:part3"))->isSelected());
        QVERIFY(edge->isSelected());
        QCOMPARE(diagram()->currentComposite(), QStringLiteral("lf1"));
        QCOMPARE(test::child<SourceView>(*m_window)->currentFile(),
                 QStringLiteral("src/planning/planning/planner.py"));
        QCOMPARE(talkers()->summary(), QStringLiteral("Talkers on topic /detections in system"));
        test::saveScreenshot(*m_window, QStringLiteral("talkers-edge.png"));
    }
};

QTEST_MAIN(TestTalkers)
#include "tst_talkers.moc"
