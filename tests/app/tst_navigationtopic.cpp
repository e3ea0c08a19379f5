// Back to a topic clicked in the composed diagram shows the whole place again: the topic
// selected in the diagram, the inspector on the topic and the Talkers panel listing who talks
// on it; showing it again records no place of its own, so Forward still goes where the person
// went next. On the example workspace, driven as a person drives the window, found through the
// window's object tree.
#include "app/mainwindow.h"
#include "app/navigationcontroller.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "support/diagramwait.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"
#include "widgets/inspectorpanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/nodefilterproxymodel.h"
#include "widgets/talkerspanel.h"

#include <QAction>
#include <QSettings>
#include <QTemporaryDir>
#include <QTreeView>
#include <QTreeWidget>
#include <QtTest>

using namespace rosarch;
using Panel = NavigationPlace::Panel;

namespace {

/// What the Talkers panel lists: its summary, then one line per row.
QStringList talkersText(const TalkersPanel *panel)
{
    QStringList out{panel->summary()};
    const QTreeWidget *tree = panel->tree();
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        const QTreeWidgetItem *head = tree->topLevelItem(i);
        out << head->text(0);
        for (int j = 0; j < head->childCount(); ++j)
            out << QStringLiteral("  %1 | %2 | %3")
                       .arg(head->child(j)->text(0), head->child(j)->text(1),
                            head->child(j)->text(2));
    }
    return out;
}

/// What the inspector shows, as one line.
QString inspectorText(const InspectorPanel *panel)
{
    return panel->info().kind + QStringLiteral(": ") + panel->info().name;
}

} // namespace

class TestNavigationTopic : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    MainWindow *m_window = nullptr;

    template <typename T> T *find() const { return test::child<T>(*m_window); }
    Document *doc() const { return find<Document>(); }
    DiagramPanel *diagram() const { return find<DiagramPanel>(); }
    NavigationHistory *history() const { return find<NavigationController>()->history(); }
    QAction *action(const QString &name) const { return m_window->findChild<QAction *>(name); }
    LaunchTreePanel *launchPanel() const { return find<LaunchTreePanel>(); }
    AtomicNodePanel *nodePanel() const { return find<AtomicNodePanel>(); }

    /// Lets the turn of the event loop in which a person acted end, and what views do a few
    /// turns later happen too (a deferred report there must not be a place).
    static void settle() { QTest::qWait(100); }
    void press(int key)
    {
        QWidget *target = QApplication::focusWidget() ? QApplication::focusWidget() : m_window;
        QTest::keyClick(target, Qt::Key(key), Qt::AltModifier);
    }
    /// Alt+`key`, then waits until the diagram is drawn and the views have settled.
    bool step(int key)
    {
        press(key);
        settle();
        const bool drawn = QTest::qWaitFor([this] { return !diagram()->isLayingOut(); }, 30000);
        settle();
        return drawn;
    }

    /// A topic drawn in the shown composite that someone talks on, and a point where a click
    /// hits it.
    bool findTopic(QString *key, QString *name, QPointF *at) const
    {
        const Composite *c = diagram()->architecture().composite(diagram()->currentComposite());
        if (!c)
            return false;
        for (const Channel &ch : c->channels) {
            if (ch.kind != Channel::Kind::Topic)
                continue;
            const QString k = DiagramBuilder::channelKey(ch.id);
            const DiagramItem *item = diagram()->scene()->item(k);
            if (!item)
                continue;
            const QPointF centre = item->sceneBoundingRect().center();
            if (diagram()->scene()->keyAt(centre) != k)
                continue;
            *key = k;
            *name = ch.name;
            *at = centre;
            return true;
        }
        return false;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
        QVERIFY(m_dir.isValid());
        const QString ws = m_dir.filePath(QStringLiteral("ws"));
        test::copyTree(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                           .filePath(QStringLiteral("resources/example_ws")),
                       ws);
        m_window = new MainWindow;
        m_window->resize(1600, 1000);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        QApplication::setActiveWindow(m_window);
        m_window->openWorkspace(ws);
        QTRY_VERIFY_WITH_TIMEOUT(!doc()->architecture().composites.isEmpty(), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(
            !diagram()->isLayingOut() && !diagram()->currentComposite().isEmpty(), 30000);
        QTRY_VERIFY_WITH_TIMEOUT(doc()->session()->keysReady(), 30000);
        if (diagram()->isCollapsed())
            QVERIFY(test::laidOut(*diagram(), [this] { diagram()->expandAll(); }));
        settle();
        find<NavigationController>()->clear(); // what the first result selected is no place
    }

    void cleanupTestCase() { delete m_window; }

    void backToATopicShowsItInTheInspectorAndTheTalkers()
    {
        QVERIFY(action(QStringLiteral("goBackAction")) &&
                action(QStringLiteral("goForwardAction")));
        QAction *back = action(QStringLiteral("goBackAction"));
        QAction *forward = action(QStringLiteral("goForwardAction"));
        auto *inspector = find<InspectorPanel>();
        auto *talkers = find<TalkersPanel>();
        const QString topicComposite = diagram()->currentComposite();

        // 1. A topic clicked in the diagram.
        QString topicKey, topic;
        QPointF at;
        QVERIFY2(findTopic(&topicKey, &topic, &at), "the example draws a topic");
        DiagramView *view = diagram()->view();
        view->centerOn(at);
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(at));
        settle();
        QCOMPARE(diagram()->selectedKeys(), QStringList{topicKey});
        QCOMPARE(history()->places().size(), 1);
        QCOMPARE(history()->current()->panel, Panel::Diagram);
        QCOMPARE(history()->current()->element, QStringLiteral("channel topic:") + topic);
        const QString topicInspector = inspectorText(inspector);
        const QStringList topicTalkers = talkersText(talkers);
        QVERIFY2(topicInspector.contains(topic), qPrintable(topicInspector));
        QVERIFY2(topicTalkers.first().contains(topic), qPrintable(topicTalkers.join(u'\n')));
        QVERIFY2(topicTalkers.size() > 2, "someone talks on it");

        // 2. Elsewhere: a node of another launch file in the launch tree (the diagram shows
        // that launch file), then one of its class's ports in the node list (the inspector and
        // the talkers show the port).
        auto *launchModel = find<LaunchTreeModel>();
        QString other;
        for (const NodeInstance &n : doc()->accepted().launch.nodes)
            if (other.isEmpty() && n.launchFileId != topicComposite && !n.classId.isEmpty())
                other = n.id;
        QVERIFY2(!other.isEmpty(), "the example has nodes in several launch files");
        QTreeView *launchTree = launchPanel()->treeView();
        launchTree->setFocus();
        QVERIFY(test::laidOut(*diagram(), [&] {
            launchTree->setCurrentIndex(
                launchPanel()->proxyModel()->mapFromSource(launchModel->nodeIndex(other)));
        }));
        settle();
        QVERIFY(diagram()->currentComposite() != topicComposite);
        QCOMPARE(history()->places().size(), 2);
        const QString otherInspector = inspectorText(inspector);
        QVERIFY(otherInspector != topicInspector);

        auto *nodeModel = find<AtomicNodeModel>();
        const QModelIndex port = nodeModel->index(
            0, 0, nodeModel->nodeIndex(doc()->launchDependencies().node(other)->classId));
        QVERIFY(nodeModel->port(port));
        nodePanel()->treeView()->setFocus();
        nodePanel()->treeView()->setCurrentIndex(nodePanel()->proxyModel()->mapFromSource(port));
        settle();
        QCOMPARE(history()->places().size(), 3);
        QCOMPARE(history()->current()->panel, Panel::Nodes);
        const QString portInspector = inspectorText(inspector);
        const QStringList portTalkers = talkersText(talkers);
        QVERIFY2(portInspector.startsWith(QLatin1String("Port")), qPrintable(portInspector));
        QVERIFY(portTalkers != topicTalkers);

        // Back twice: the launch row, then the topic, in another launch file drawn again.
        QVERIFY(step(Qt::Key_Left));
        QCOMPARE(history()->currentIndex(), 1);
        QVERIFY(step(Qt::Key_Left));
        QCOMPARE(history()->currentIndex(), 0);
        QCOMPARE(diagram()->currentComposite(), topicComposite);
        QCOMPARE(diagram()->selectedKeys(), QStringList{topicKey});
        QCOMPARE(inspectorText(inspector), topicInspector);
        QCOMPARE(talkersText(talkers), topicTalkers);
        // Showing it again was no visit: the places ahead are still there.
        QCOMPARE(history()->places().size(), 3);
        QVERIFY(forward->isEnabled());
        QVERIFY(!back->isEnabled());
        QVERIFY2(forward->toolTip().contains(QLatin1String("launch tree")),
                 qPrintable(forward->toolTip()));

        // Forward twice: the launch row, then the port, as they were.
        QVERIFY(step(Qt::Key_Right));
        QCOMPARE(history()->currentIndex(), 1);
        QCOMPARE(inspectorText(inspector), otherInspector);
        QVERIFY(step(Qt::Key_Right));
        QCOMPARE(history()->currentIndex(), 2);
        QCOMPARE(nodePanel()->currentSourceIndex(), port);
        QCOMPARE(inspectorText(inspector), portInspector);
        QCOMPARE(talkersText(talkers), portTalkers);
        QCOMPARE(history()->places().size(), 3);
        QVERIFY(!forward->isEnabled());

        // And back to the topic in one go from the port's launch file: the same again.
        QVERIFY(step(Qt::Key_Left));
        QVERIFY(step(Qt::Key_Left));
        QCOMPARE(diagram()->selectedKeys(), QStringList{topicKey});
        QCOMPARE(inspectorText(inspector), topicInspector);
        QCOMPARE(talkersText(talkers), topicTalkers);
        QCOMPARE(history()->places().size(), 3);
        QCOMPARE(history()->currentIndex(), 0);
    }
};

QTEST_MAIN(TestNavigationTopic)
#include "tst_navigationtopic.moc"
