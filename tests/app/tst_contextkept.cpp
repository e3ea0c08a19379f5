// Corrections keep the person's place: after a correction, a decision on a suggestion, an undo
// or a redo, the main window shows what it showed before: the filters typed over the node list
// and the launch tree, the current rows (found again by stable key when the rows change under
// them), the composed diagram's zoom, scrolled place and selection, and the source pane's file,
// cursor and scrolled line. On the example workspace, driven as a person drives the window.
#include "app/correctioncontroller.h"
#include "app/correctioneditor.h"
#include "app/mainwindow.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "suggestions/suggestionengine.h"
#include "support/diagramwait.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/correctiondialog.h"
#include "widgets/diagram/diagramitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/nodefilterproxymodel.h"
#include "widgets/sourceview.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QLineEdit>
#include <QScrollBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeView>
#include <QUndoStack>
#include <QtTest>

using namespace rosarch;
using EKind = CorrectionController::Element::Kind;

namespace {

/// What a person sees of their place in the window.
struct Place
{
    QString nodeFilter;
    QString launchFilter;
    QString nodeRow;   ///< the node list's current element ("arc_3/p1") and its stable key
    QString launchRow; ///< the launch tree's current instance and its stable key
    int nodeScroll = 0;
    QString composite;
    qreal zoom = 0;
    QPoint selectedAt; ///< where the selected element's corner is in the view
    /// The diagram's scroll bars at an end: a new layout may leave no room to keep the
    /// element where it was in that direction.
    bool atEndX = false;
    bool atEndY = false;
    QStringList diagramSelection;
    QString sourceFile;
    int cursorLine = -1;
    int cursorIndex = -1;
    int firstLine = -1;

    QString text() const
    {
        return QStringLiteral("filters '%1' '%2'; rows %3 | %4 (scrolled %5); diagram %6 at %7, "
                              "selected %10 at (%8, %9) in the view; source %11:%12:%13 from %14")
            .arg(nodeFilter, launchFilter, nodeRow, launchRow)
            .arg(nodeScroll)
            .arg(composite)
            .arg(zoom)
            .arg(selectedAt.x())
            .arg(selectedAt.y())
            .arg(diagramSelection.join(u','), sourceFile)
            .arg(cursorLine)
            .arg(cursorIndex)
            .arg(firstLine);
    }
    /// The same place: the element in the view may move by the rounding of the scroll bars.
    bool same(const Place &o) const
    {
        return nodeFilter == o.nodeFilter && launchFilter == o.launchFilter &&
               nodeRow == o.nodeRow && launchRow == o.launchRow && nodeScroll == o.nodeScroll &&
               composite == o.composite && qFuzzyCompare(zoom, o.zoom) &&
               (std::abs(selectedAt.x() - o.selectedAt.x()) <= 1 || atEndX) &&
               (std::abs(selectedAt.y() - o.selectedAt.y()) <= 1 || atEndY) &&
               diagramSelection == o.diagramSelection && sourceFile == o.sourceFile &&
               cursorLine == o.cursorLine && cursorIndex == o.cursorIndex &&
               firstLine == o.firstLine;
    }
};

} // namespace

class TestContextKept : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    MainWindow *m_window = nullptr;

    Document *doc() const { return test::child<Document>(*m_window); }
    DiagramPanel *diagram() const { return test::child<DiagramPanel>(*m_window); }

    Place place() const
    {
        Place p;
        p.nodeFilter = test::child<AtomicNodePanel>(*m_window)->filterEdit()->text();
        p.launchFilter = test::child<LaunchTreePanel>(*m_window)->filterEdit()->text();
        const QModelIndex node = test::child<AtomicNodePanel>(*m_window)->currentSourceIndex();
        p.nodeRow = test::child<AtomicNodeModel>(*m_window)->elementId(node) + u' ' +
                    test::child<AtomicNodeModel>(*m_window)->stableKey(node);
        const QModelIndex launch = test::child<LaunchTreePanel>(*m_window)->currentSourceIndex();
        p.launchRow = launch.data(LaunchTreeModel::InstanceIdRole).toString() + u' ' +
                      test::child<LaunchTreeModel>(*m_window)->stableKey(launch);
        p.nodeScroll =
            test::child<AtomicNodePanel>(*m_window)->treeView()->verticalScrollBar()->value();
        p.composite = diagram()->currentComposite();
        DiagramView *view = diagram()->view();
        p.zoom = view->zoom();
        p.diagramSelection = diagram()->selectedKeys();
        const auto atEnd = [](const QScrollBar *bar) {
            return bar->value() == bar->minimum() || bar->value() == bar->maximum();
        };
        p.atEndX = atEnd(view->horizontalScrollBar());
        p.atEndY = atEnd(view->verticalScrollBar());
        if (!p.diagramSelection.isEmpty())
            if (const DiagramItem *item = diagram()->scene()->item(p.diagramSelection.first()))
                p.selectedAt = view->mapFromScene(item->sceneBoundingRect().topLeft());
        const SourceView *source = test::child<SourceView>(*m_window);
        p.sourceFile = source->currentFile();
        source->editor()->getCursorPosition(&p.cursorLine, &p.cursorIndex);
        p.firstLine = source->editor()->firstVisibleLine();
        return p;
    }

    /// Runs `step` (a correction, an undo, ...) and waits until the diagram is drawn again.
    template <typename F> void redrawnAfter(F &&step)
    {
        QVERIFY(test::laidOut(*diagram(), std::forward<F>(step)));
        QCoreApplication::processEvents();
    }

    /// `step`, then its undo and redo: the place is the same after each.
    template <typename F> void keptThrough(const QString &what, F &&step)
    {
        const Place before = place();
        const int count = doc()->undoStack()->count();
        redrawnAfter(step);
        QCOMPARE(doc()->undoStack()->count(), count + 1); // it did change the model
        QVERIFY2(place().same(before),
                 qPrintable(what + QStringLiteral(":\n  before ") + before.text() +
                            QStringLiteral("\n  after  ") + place().text()));
        redrawnAfter([this] { doc()->undoStack()->undo(); });
        QVERIFY2(place().same(before),
                 qPrintable(what + QStringLiteral(", undone:\n  before ") + before.text() +
                            QStringLiteral("\n  after  ") + place().text()));
        redrawnAfter([this] { doc()->undoStack()->redo(); });
        QVERIFY2(place().same(before),
                 qPrintable(what + QStringLiteral(", redone:\n  before ") + before.text() +
                            QStringLiteral("\n  after  ") + place().text()));
    }

    QString instanceNamed(const QString &name) const
    {
        for (const NodeInstance &n : doc()->accepted().launch.nodes)
            if (n.nodeName == name)
                return n.id;
        return {};
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).removeRecursively();
        qputenv("ROSARCH_AUTHOR", "tester");
        QVERIFY(m_dir.isValid());
        const QString ws = m_dir.filePath(QStringLiteral("ws"));
        test::copyTree(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                           .filePath(QStringLiteral("resources/example_ws")),
                       ws);
        m_window = new MainWindow;
        m_window->resize(1600, 1000);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        // The layout a 1600 x 1000 window gets (the window was built at its small first size).
        QTRY_COMPARE(m_window->width(), 1600);
        for (QAction *a : m_window->findChildren<QAction *>())
            if (a->text() == QStringLiteral("&Reset Layout"))
                a->trigger();
        m_window->openWorkspace(ws);
        QTRY_VERIFY_WITH_TIMEOUT(!doc()->architecture().composites.isEmpty(), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(
            !diagram()->isLayingOut() && !diagram()->currentComposite().isEmpty(), 30000);
        QTRY_VERIFY(doc()->session()->keysReady());
        test::child<CorrectionEditor>(*m_window)->setDialogHandler([](CorrectionDialog &d) {
            const QString title = d.windowTitle();
            if (title == QLatin1String("Add Connection")) {
                d.setPortKind(PortKind::Subscriber);
                d.setName(QStringLiteral("/robot1/mission_status"));
                d.setType(QStringLiteral("robot_interfaces/msg/MissionStatus"));
            } else if (title == QLatin1String("Add Port")) {
                d.setPortKind(PortKind::Publisher);
                d.setName(QStringLiteral("heartbeat"));
                d.setType(QStringLiteral("std_msgs/msg/Empty"));
            } else if (title == QLatin1String("Add Part")) {
                if (!d.setChoice(QStringLiteral(
                        "class:robot_mission|robot_mission.mode_manager.ModeManager")))
                    return false;
                d.setName(QStringLiteral("spare_modes"));
            } else if (title == QLatin1String("Rename")) {
                d.setName(d.name() + QStringLiteral("_renamed"));
            }
            d.setReason(QStringLiteral("a test"));
            return true;
        });
    }

    void cleanupTestCase() { delete m_window; }

    void aPersonFindsTheirPlace()
    {
        // Types a filter in both trees, picks the navigator in the launch tree (the node list
        // follows with its class), then one of its ports in the node list (the source shows
        // its line), scrolls the source, and zooms and scrolls the diagram.
        QTest::keyClicks(test::child<LaunchTreePanel>(*m_window)->filterEdit(),
                         QStringLiteral("nav"));
        QTest::keyClicks(test::child<AtomicNodePanel>(*m_window)->filterEdit(),
                         QStringLiteral("nav"));
        QTest::qWait(400); // the launch tree waits for a pause in typing on a slow filter
        const QString navigator = instanceNamed(QStringLiteral("navigator"));
        QVERIFY(!navigator.isEmpty());
        QTreeView *launchTree = test::child<LaunchTreePanel>(*m_window)->treeView();
        const QModelIndex launchRow =
            test::child<LaunchTreePanel>(*m_window)->proxyModel()->mapFromSource(
                test::child<LaunchTreeModel>(*m_window)->nodeIndex(navigator));
        QVERIFY2(launchRow.isValid(), "the filter shows the navigator");
        redrawnAfter([&] { launchTree->setCurrentIndex(launchRow); });
        const QString classId = doc()->launchDependencies().node(navigator)->classId;
        QCOMPARE(test::child<AtomicNodePanel>(*m_window)->currentSourceIndex(),
                 test::child<AtomicNodeModel>(*m_window)->nodeIndex(classId));
        const QModelIndex port = test::child<AtomicNodeModel>(*m_window)->index(
            1, 0, test::child<AtomicNodeModel>(*m_window)->nodeIndex(classId));
        QVERIFY(port.isValid());
        test::child<AtomicNodePanel>(*m_window)->treeView()->setCurrentIndex(
            test::child<AtomicNodePanel>(*m_window)->proxyModel()->mapFromSource(port));
        QVERIFY(test::child<SourceView>(*m_window)->currentFile().endsWith(
            QLatin1String("navigator.cpp")));
        test::child<SourceView>(*m_window)->editor()->setFirstVisibleLine(3);

        DiagramView *view = diagram()->view();
        view->setZoom(1.6);
        QCoreApplication::processEvents(); // the scroll bars the zoom brings, before scrolling
        view->horizontalScrollBar()->setValue(
            (view->horizontalScrollBar()->minimum() + view->horizontalScrollBar()->maximum()) / 2);
        view->verticalScrollBar()->setValue(
            (view->verticalScrollBar()->minimum() + view->verticalScrollBar()->maximum()) / 3);
        QVERIFY2(view->horizontalScrollBar()->maximum() > 0, "the diagram is scrolled");
        QVERIFY(!diagram()->selectedKeys().isEmpty()); // the navigator, from the launch tree
        test::saveScreenshot(*m_window, QStringLiteral("context-before.png"));
        const Place p = place();
        QCOMPARE(p.nodeFilter, QStringLiteral("nav"));
        QCOMPARE(p.launchFilter, QStringLiteral("nav"));
        QVERIFY(p.nodeRow.contains(QLatin1String("port:")));
        QVERIFY(p.launchRow.contains(QLatin1String("instance:")));
        QVERIFY(p.firstLine == 3 && p.cursorLine > 0);
    }

    void aConnectionKeepsThePlace()
    {
        keptThrough(QStringLiteral("Add Connection"), [this] {
            QVERIFY(test::child<CorrectionEditor>(*m_window)->addConnection(
                {EKind::Instance, instanceNamed(QStringLiteral("navigator")), {}, {}}));
        });
        // the connection was made, in the diagram shown too
        bool wired = false;
        for (const Channel &ch :
             doc()->accepted().architecture.composite(QStringLiteral("lf1"))->channels)
            wired = wired || ch.name == QLatin1String("/robot1/mission_status");
        QVERIFY(wired);
    }

    void aRenameKeepsThePlace()
    {
        keptThrough(QStringLiteral("Rename"), [this] {
            QVERIFY(test::child<CorrectionEditor>(*m_window)->rename(
                {EKind::Instance, instanceNamed(QStringLiteral("mode_manager")), {}, {}}));
        });
    }

    void anAddedPortReshapesTheNodeListAndKeepsThePlace()
    {
        // The node list's rows change under the current port row.
        const QString classId =
            doc()->launchDependencies().node(instanceNamed(QStringLiteral("navigator")))->classId;
        keptThrough(QStringLiteral("Add Port"), [&] {
            QVERIFY(
                test::child<CorrectionEditor>(*m_window)->addPort({EKind::Class, classId, {}, {}}));
        });
        QVERIFY(test::child<AtomicNodeModel>(*m_window)->rowCount(
                    test::child<AtomicNodeModel>(*m_window)->nodeIndex(classId)) > 0);
    }

    void anAddedPartReshapesTheLaunchTreeAndKeepsThePlace()
    {
        QString mission;
        for (const LaunchFileInstance &lf : doc()->accepted().launch.instances)
            if (lf.file.endsWith(QLatin1String("mission.launch.yaml")))
                mission = lf.id;
        QVERIFY(!mission.isEmpty());
        keptThrough(QStringLiteral("Add Part"), [&] {
            QVERIFY(test::child<CorrectionEditor>(*m_window)->addPart(
                {EKind::LaunchFile, mission, {}, {}}));
        });
    }

    void aDecisionOnASuggestionKeepsThePlace()
    {
        doc()->session()->setSuggestions(SuggestionEngine(doc()->workspaceRoot(),
                                                          doc()->recovered(),
                                                          SuggestionEngine::Options())
                                             .run());
        QCoreApplication::processEvents();
        QString description, grouping;
        for (const Suggestion &s : doc()->session()->suggestions()) {
            if (s.kind == Suggestion::Kind::NodeDescription && description.isEmpty())
                description = s.id;
            if (s.kind == Suggestion::Kind::SubsystemGrouping && grouping.isEmpty())
                grouping = s.id;
        }
        QVERIFY(!description.isEmpty() && !grouping.isEmpty());
        keptThrough(QStringLiteral("Accept a description"),
                    [&] { QVERIFY(doc()->session()->acceptSuggestion(description)); });
        keptThrough(QStringLiteral("Accept a grouping"),
                    [&] { QVERIFY(doc()->session()->acceptSuggestion(grouping)); });
        keptThrough(QStringLiteral("Reject a description"),
                    [&] { QVERIFY(doc()->session()->rejectSuggestion(description)); });
        test::saveScreenshot(*m_window, QStringLiteral("context-after.png"));
    }

    void aGroupingKeepsThePlaceInTheSmallLayout()
    {
        // At 1024 x 700, at a zoom where a grouping accepted brings or drops a scroll bar: the
        // element looked at stays on its pixel.
        MainWindow *large = std::exchange(m_window, new MainWindow);
        const auto back = qScopeGuard([&] { delete std::exchange(m_window, large); });
        m_window->resize(1024, 700);
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
        QTRY_COMPARE(m_window->width(), 1024);
        for (QAction *a : m_window->findChildren<QAction *>())
            if (a->text() == QStringLiteral("&Reset Layout"))
                a->trigger();
        const QString ws = m_dir.filePath(QStringLiteral("small"));
        test::copyTree(QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                           .filePath(QStringLiteral("resources/example_ws")),
                       ws);
        m_window->openWorkspace(ws);
        QTRY_VERIFY_WITH_TIMEOUT(!doc()->architecture().composites.isEmpty(), 60000);
        QTRY_VERIFY_WITH_TIMEOUT(
            !diagram()->isLayingOut() && !diagram()->currentComposite().isEmpty(), 30000);
        QTRY_VERIFY(doc()->session()->keysReady());
        doc()->session()->setSuggestions(SuggestionEngine(doc()->workspaceRoot(),
                                                          doc()->recovered(),
                                                          SuggestionEngine::Options())
                                             .run());
        QCoreApplication::processEvents();
        QStringList groupings;
        for (const Suggestion &s : doc()->session()->suggestions())
            if (s.kind == Suggestion::Kind::SubsystemGrouping)
                groupings << s.id;
        // A composite whose drawing a grouping changes.
        QString grouping, composite;
        QSizeF without, with;
        for (const QString &id : groupings)
            for (const Composite &c : doc()->architecture().composites) {
                if (!grouping.isEmpty())
                    break;
                QVERIFY(test::laidOut(*diagram(), [&] { diagram()->showComposite(c.instanceId); }));
                without = diagram()->scene()->sceneRect().size();
                redrawnAfter([&] { QVERIFY(doc()->session()->acceptSuggestion(id)); });
                with = diagram()->scene()->sceneRect().size();
                redrawnAfter([this] { doc()->undoStack()->undo(); });
                if (with != without && diagram()->currentComposite() == c.instanceId) {
                    grouping = id;
                    composite = c.instanceId;
                }
            }
        QVERIFY2(!grouping.isEmpty(), "a grouping changes a drawing");

        // The zoom between the two: a scroll bar comes with the grouping (across the one that
        // stays in the other direction), and one of the composite's boxes selected in sight.
        QVERIFY(test::laidOut(*diagram(), [&] { diagram()->showComposite(composite); }));
        DiagramView *view = diagram()->view();
        const bool taller = with.height() != without.height();
        const QSize shown = view->viewport()->size();
        view->setZoom(taller ? 2.0 * shown.height() / (with.height() + without.height())
                             : 2.0 * shown.width() / (with.width() + without.width()));
        QCoreApplication::processEvents();
        QScrollBar *bar = taller ? view->verticalScrollBar() : view->horizontalScrollBar();
        QString selected;
        for (const RosNodePart &p : diagram()->architecture().composite(composite)->parts)
            if (DiagramItem *item = diagram()->scene()->item(DiagramBuilder::partKey(p.id));
                item && selected.isEmpty() &&
                view->viewport()->rect().contains(
                    view->mapFromScene(item->sceneBoundingRect()).boundingRect()))
                selected = DiagramBuilder::partKey(p.id);
        QVERIFY2(!selected.isEmpty(), "a box in sight");
        diagram()->selectElement(selected);
        QCoreApplication::processEvents();
        const auto at = [&] {
            return view->mapFromScene(
                diagram()->scene()->item(selected)->sceneBoundingRect().topLeft());
        };
        const QPoint before = at();
        const bool barBefore = bar->isVisible();
        redrawnAfter([&] { QVERIFY(doc()->session()->acceptSuggestion(grouping)); });
        QVERIFY2(bar->isVisible() != barBefore, "the grouping brings or drops a scroll bar");
        // On its pixel, but in a direction whose scroll bar is at an end (no room to keep it).
        const auto kept = [view](const QPoint &now, const QPoint &was) {
            const auto room = [](const QScrollBar *b) {
                return b->value() != b->minimum() && b->value() != b->maximum();
            };
            return (std::abs(now.x() - was.x()) <= 1 || !room(view->horizontalScrollBar())) &&
                   (std::abs(now.y() - was.y()) <= 1 || !room(view->verticalScrollBar())) &&
                   (room(view->horizontalScrollBar()) || room(view->verticalScrollBar()));
        };
        const QPoint accepted = at();
        QVERIFY2(kept(accepted, before),
                 qPrintable(QStringLiteral("accepted: (%1, %2) was (%3, %4)")
                                .arg(accepted.x())
                                .arg(accepted.y())
                                .arg(before.x())
                                .arg(before.y())));
        // Undone, the drawing fits the view again in one direction, which then places it;
        // redone, it is where it was with the grouping.
        redrawnAfter([this] { doc()->undoStack()->undo(); });
        redrawnAfter([this] { doc()->undoStack()->redo(); });
        const QPoint redone = at();
        QVERIFY2(kept(redone, accepted), qPrintable(QStringLiteral("redone: (%1, %2) was (%3, %4)")
                                                        .arg(redone.x())
                                                        .arg(redone.y())
                                                        .arg(accepted.x())
                                                        .arg(accepted.y())));
    }
};

QTEST_MAIN(TestContextKept)
#include "tst_contextkept.moc"
