// Back and forward over every panel: a launch row, a port in the node list, a topic clicked in
// the composed diagram, a finding in the Log and a line in the source are each one place; Alt+Left,
// Alt+Right, the mouse's back and forward buttons and Go ▸ Back / Forward show them again in
// every view, found by stable key; the actions are enabled only when there is somewhere to go.
// On the example workspace, driven as a person drives the window.
#include "app/mainwindow.h"
#include "app/navigationcontroller.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "support/diagramwait.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/diagram/diagramitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/nodefilterproxymodel.h"
#include "widgets/sourceview.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QLineEdit>
#include <QMenuBar>
#include <QSettings>
#include <QTemporaryDir>
#include <QToolBar>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;
using Panel = NavigationPlace::Panel;

class TestNavigation : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    MainWindow *m_window = nullptr;

    Document *doc() const { return test::child<Document>(*m_window); }
    DiagramPanel *diagram() const { return test::child<DiagramPanel>(*m_window); }
    NavigationController *nav() const { return test::child<NavigationController>(*m_window); }
    QAction *back() const { return nav()->backAction(); }
    QAction *forward() const { return nav()->forwardAction(); }

    QString instanceNamed(const QString &name) const
    {
        for (const NodeInstance &n : doc()->accepted().launch.nodes)
            if (n.nodeName == name)
                return n.id;
        return {};
    }
    QString launchRow() const
    {
        return test::child<LaunchTreePanel>(*m_window)
            ->currentSourceIndex()
            .data(LaunchTreeModel::InstanceIdRole)
            .toString();
    }
    QString nodeRow() const
    {
        return test::child<AtomicNodeModel>(*m_window)->elementId(
            test::child<AtomicNodePanel>(*m_window)->currentSourceIndex());
    }
    /// Lets the turn of the event loop in which a person acted end: then it is one place.
    static void settle() { QTest::qWait(20); }
    /// Presses a key where the person works: in the widget with the focus.
    void press(int key, Qt::KeyboardModifiers modifiers = Qt::AltModifier)
    {
        QWidget *target = QApplication::focusWidget() ? QApplication::focusWidget() : m_window;
        QTest::keyClick(target, Qt::Key(key), modifiers);
        settle();
    }
    bool waitForLayout()
    {
        return !diagram()->isLayingOut() ||
               QSignalSpy(diagram(), &DiagramPanel::layoutFinished).wait(30000);
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
        QTRY_VERIFY_WITH_TIMEOUT(doc()->session()->keysReady(),
                                 30000); // slow under a loaded CI machine
        settle();
        nav()->clear(); // what the first result selected by itself is not the person's
    }

    void cleanupTestCase() { delete m_window; }

    void theActionsAreInTheGoMenuAndTheToolbar()
    {
        QMenu *go = nullptr;
        for (QAction *a : m_window->menuBar()->actions())
            if (a->text() == QLatin1String("&Go"))
                go = a->menu();
        QVERIFY(go);
        QCOMPARE(go->actions(), (QList<QAction *>{back(), forward()}));
        auto *toolBar = m_window->findChild<QToolBar *>(QStringLiteral("mainToolBar"));
        QVERIFY(toolBar && toolBar->actions().contains(back()) &&
                toolBar->actions().contains(forward()));
        QCOMPARE(back()->shortcut(), QKeySequence(Qt::ALT | Qt::Key_Left));
        QCOMPARE(forward()->shortcut(), QKeySequence(Qt::ALT | Qt::Key_Right));
        // Nothing visited yet: nowhere to go.
        QVERIFY(!back()->isEnabled());
        QVERIFY(!forward()->isEnabled());
    }

    void eachPanelIsAPlaceAndBackShowsThemAgain()
    {
        // 1. The navigator in the launch tree (the node list follows with its class).
        const QString navigator = instanceNamed(QStringLiteral("navigator"));
        QVERIFY(!navigator.isEmpty());
        QTreeView *launchTree = test::child<LaunchTreePanel>(*m_window)->treeView();
        launchTree->setFocus();
        QVERIFY(test::laidOut(*diagram(), [&] {
            launchTree->setCurrentIndex(
                test::child<LaunchTreePanel>(*m_window)->proxyModel()->mapFromSource(
                    test::child<LaunchTreeModel>(*m_window)->nodeIndex(navigator)));
        }));
        settle();
        QCOMPARE(nav()->history()->places().size(), 1); // the class that followed is no place
        const NavigationPlace first = *nav()->history()->current();
        QCOMPARE(first.panel, Panel::Launch);
        QCOMPARE(first.key, test::child<LaunchTreeModel>(*m_window)->stableKey(
                                test::child<LaunchTreeModel>(*m_window)->nodeIndex(navigator)));
        QVERIFY2(first.key.startsWith(QLatin1String("instance:")), qPrintable(first.key));
        QVERIFY(!back()->isEnabled());
        const QString navigatorClass = nodeRow();
        QVERIFY(!navigatorClass.isEmpty());

        // 2. One of its ports in the node list: the source shows the port's line.
        const QModelIndex classIndex =
            test::child<AtomicNodeModel>(*m_window)->nodeIndex(navigatorClass);
        const QModelIndex port = test::child<AtomicNodeModel>(*m_window)->index(1, 0, classIndex);
        QVERIFY(port.isValid());
        test::child<AtomicNodePanel>(*m_window)->treeView()->setFocus();
        test::child<AtomicNodePanel>(*m_window)->treeView()->setCurrentIndex(
            test::child<AtomicNodePanel>(*m_window)->proxyModel()->mapFromSource(port));
        settle();
        const QString portRow = nodeRow();
        QCOMPARE(nav()->history()->current()->panel, Panel::Nodes);
        QVERIFY(nav()->history()->current()->key.startsWith(QLatin1String("port:")));
        const QString portFile = test::child<SourceView>(*m_window)->currentFile();
        int portLine = -1, index = 0;
        test::child<SourceView>(*m_window)->editor()->getCursorPosition(&portLine, &index);
        QVERIFY(portLine > 0);
        QVERIFY(back()->isEnabled());
        QVERIFY(back()->toolTip().contains(QLatin1String("launch tree")));

        // 3. Another node's box clicked in the diagram: the launch tree follows it.
        if (diagram()->isCollapsed())
            QVERIFY(test::laidOut(*diagram(), [this] { diagram()->expandAll(); }));
        const Composite *c = diagram()->architecture().composite(diagram()->currentComposite());
        QVERIFY(c);
        const RosNodePart *other = nullptr;
        for (const RosNodePart &part : c->parts)
            if (!other && part.kind == RosNodePart::Kind::Node && part.instanceId != navigator)
                other = &part;
        QVERIFY(other);
        const QString partKey = DiagramBuilder::partKey(other->id);
        const QString otherInstance = other->instanceId;
        DiagramItem *item = diagram()->scene()->item(partKey);
        QVERIFY(item);
        DiagramView *view = diagram()->view();
        view->centerOn(item);
        // Its title row: the part, not one of its ports (nor the namespace around it).
        const QRectF box = item->sceneBoundingRect();
        QPointF title;
        for (qreal y = box.top() + 2; y < box.bottom() && title.isNull(); y += 2)
            if (diagram()->scene()->keyAt({box.center().x(), y}) == partKey)
                title = {box.center().x(), y};
        QVERIFY(!title.isNull());
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->mapFromScene(title));
        settle();
        QCOMPARE(diagram()->selectedKeys(), QStringList{partKey});
        QCOMPARE(launchRow(), otherInstance);
        QCOMPARE(nav()->history()->current()->panel, Panel::Diagram);
        QCOMPARE(nav()->history()->current()->element,
                 QStringLiteral("part ") + doc()->session()->keyOf(otherInstance));

        // 4. A finding in the Log.
        QTreeView *findings = test::child<LogView>(*m_window)->diagnosticsView();
        QModelIndex finding;
        for (int row = 0; row < findings->model()->rowCount() && !finding.isValid(); ++row) {
            const QModelIndex i = findings->model()->index(row, 0);
            finding = i.data(DiagnosticModel::KeyRole).toString().isEmpty()
                          ? findings->model()->index(0, 0, i) // a group: its first finding
                          : i;
        }
        QVERIFY2(finding.isValid(), "the example has findings");
        const QString findingKey = finding.data(DiagnosticModel::KeyRole).toString();
        findings->setFocus();
        findings->setCurrentIndex(finding);
        settle();
        QCOMPARE(nav()->history()->current()->panel, Panel::Findings);
        QCOMPARE(nav()->history()->current()->key, findingKey);
        QCOMPARE(nav()->history()->places().size(), 4);
        QVERIFY(!forward()->isEnabled());

        // Alt+Left: the diagram's topic again, then the port (and its line), then the
        // navigator's launch row.
        findings->setCurrentIndex({}); // elsewhere in the Log: no place of its own
        press(Qt::Key_Left);
        QCOMPARE(diagram()->selectedKeys(), QStringList{partKey});
        QVERIFY(forward()->isEnabled());
        press(Qt::Key_Left);
        QCOMPARE(nodeRow(), portRow);
        QCOMPARE(test::child<SourceView>(*m_window)->currentFile(), portFile);
        int line = -1;
        test::child<SourceView>(*m_window)->editor()->getCursorPosition(&line, &index);
        QCOMPARE(line, portLine);
        press(Qt::Key_Left);
        QCOMPARE(launchRow(), navigator);
        QCOMPARE(nodeRow(), navigatorClass);
        QVERIFY(!back()->isEnabled());
        QCOMPARE(nav()->history()->places().size(), 4); // going back visits nothing

        // Alt+Right twice, then forward by the mouse's forward button over the diagram.
        press(Qt::Key_Right);
        QCOMPARE(nodeRow(), portRow);
        press(Qt::Key_Right);
        QCOMPARE(diagram()->selectedKeys(), QStringList{partKey});
        QCOMPARE(launchRow(), otherInstance); // the views that followed it follow again
        QTest::mousePress(diagram()->view()->viewport(), Qt::ForwardButton);
        QTest::mouseRelease(diagram()->view()->viewport(), Qt::ForwardButton);
        settle();
        QCOMPARE(findings->currentIndex().data(DiagnosticModel::KeyRole).toString(), findingKey);
        QVERIFY(!forward()->isEnabled());

        // The mouse's back button over the node list.
        QTest::mousePress(test::child<AtomicNodePanel>(*m_window)->treeView()->viewport(),
                          Qt::BackButton);
        QTest::mouseRelease(test::child<AtomicNodePanel>(*m_window)->treeView()->viewport(),
                            Qt::BackButton);
        settle();
        QCOMPARE(diagram()->selectedKeys(), QStringList{partKey});
        QCOMPARE(nav()->history()->currentIndex(), 2);

        // A new place after going back drops the places ahead, as a browser does.
        press(Qt::Key_Left);
        QCOMPARE(nav()->history()->currentIndex(), 1);
        test::child<AtomicNodePanel>(*m_window)->treeView()->setCurrentIndex(
            test::child<AtomicNodePanel>(*m_window)->proxyModel()->mapFromSource(classIndex));
        settle();
        QCOMPARE(nav()->history()->places().size(), 3);
        QVERIFY(!forward()->isEnabled());
        QVERIFY(back()->isEnabled());
    }

    void placesAreFoundByKeyNotRow()
    {
        // The node list filtered: the rows above the port are others now, the place is the same.
        QVERIFY(nav()->history()->canGoBack());
        const NavigationPlace *portPlace = &nav()->history()->places().at(1);
        QCOMPARE(portPlace->panel, Panel::Nodes);
        const QModelIndex port =
            test::child<AtomicNodeModel>(*m_window)->indexOfStableKey(portPlace->key);
        QVERIFY(port.isValid());
        const QString portId = test::child<AtomicNodeModel>(*m_window)->elementId(port);
        QTest::keyClicks(test::child<AtomicNodePanel>(*m_window)->filterEdit(),
                         QStringLiteral("nav"));
        QTRY_VERIFY(test::child<AtomicNodePanel>(*m_window)->proxyModel()->rowCount() > 0);
        press(Qt::Key_Left);
        QCOMPARE(nodeRow(), portId);
    }

    void aLineInTheSourceIsAPlace()
    {
        const int at = nav()->history()->currentIndex();
        QsciScintilla *editor = test::child<SourceView>(*m_window)->editor();
        editor->setFocus();
        int line = -1, index = 0;
        editor->getCursorPosition(&line, &index);
        // (the history takes the place once the event loop has turned: a loaded machine is slow)
        editor->setCursorPosition(line + 3, 0); // the person moves down three lines
        settle();
        QTRY_COMPARE(nav()->history()->current()->panel, Panel::Source);
        QTRY_COMPARE(nav()->history()->current()->sourceLine, line + 3);
        const int moved = line + 5;
        editor->setCursorPosition(moved, 0); // moving on in the same file: the same place
        settle();
        QTRY_COMPARE(nav()->history()->current()->sourceLine, moved);
        QCOMPARE(nav()->history()->currentIndex(), at + 1);
        QCOMPARE(int(nav()->history()->places().size()), at + 2); // the places ahead dropped
        // Alt+Left in the editor goes back (the editor does not keep the key for itself).
        QTest::keyClick(editor, Qt::Key_Left, Qt::AltModifier);
        settle();
        QTRY_COMPARE(nav()->history()->currentIndex(), at);
        QTest::keyClick(editor, Qt::Key_Right, Qt::AltModifier);
        settle();
        int now = -1;
        editor->getCursorPosition(&now, &index);
        QCOMPARE(now, moved);
    }
};

QTEST_MAIN(TestNavigation)
#include "tst_navigation.moc"
