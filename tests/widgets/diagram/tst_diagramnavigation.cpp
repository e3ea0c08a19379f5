// Finding one's way in a big system: the root picker in the diagram's header, the prompt when
// no root stands out, the overview a diagram too big to read at fit starts in (text never
// below the legible size), expanding and collapsing its boxes, and the minimap.
#include "diagram/diagramlayouter.h"
#include "support/diagramarchitecture.h"
#include "support/diagramwait.h"
#include "support/screenshot.h"
#include "widgets/diagram/diagramclusteritem.h"
#include "widgets/diagram/diagramminimap.h"
#include "widgets/diagram/diagramnodeitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramrootpicker.h"
#include "widgets/diagram/diagramrootprompt.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"

#include <QAbstractItemView>
#include <QAction>
#include <QCompleter>
#include <QLineEdit>
#include <QListWidget>
#include <QScrollBar>
#include <QSignalSpy>
#include <QtTest>

using namespace rosarch;
using rosarch::test::laidOut;
using rosarch::test::saveScreenshot;

namespace {

/// Two roots: the demo (including its listener) and a fleet of `robots`.
Architecture twoRoots(int robots)
{
    Architecture arch = test::diagram::architecture();
    arch.composites << test::diagram::fleet(robots);
    return arch;
}

/// The on-screen pixel height of the diagram's name text at the view's zoom.
double namePixels(DiagramPanel &panel)
{
    return panel.scene()->diagramStyle().textFont.pixelSize() * panel.view()->zoom();
}

double legiblePixels(DiagramPanel &panel)
{
    return DiagramPanel::kLegiblePoints * panel.logicalDpiY() / 72.0;
}

} // namespace

class TestDiagramNavigation : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void pickerListsAndSwitchesRoots();
    void pickerFitsItsListsWhenTheyOpen();
    void askingListsTheRoots();
    void tooBigStartsAsAnOverview();
    void minimapShowsAndPans();
    void fitStartsAtTheFirstBoxWhenTheCornerIsEmpty();
    void theFramesTabStaysInsideTheFrame();
    void pickerListsRootsByName();
};

void TestDiagramNavigation::pickerListsAndSwitchesRoots()
{
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(1400, 900);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const Architecture arch = twoRoots(2);
    QVERIFY(laidOut(panel, [&] {
        panel.setArchitecture(arch, {},
                              RootChoice{QStringLiteral("lf9"), RootChoice::Reason::Name});
    }));
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf9"));
    DiagramRootPicker *picker = panel.rootPicker();
    QCOMPARE(picker->count(), 2);
    QCOMPARE(picker->itemText(0), QStringLiteral("demo — 1 include"));
    QCOMPARE(picker->itemText(1), QStringLiteral("fleet — 0 includes"));
    QCOMPARE(picker->currentRoot(), QStringLiteral("lf9"));
    QVERIFY(picker->itemData(0, Qt::ToolTipRole).toString().contains("src/demo/launch/demo"));
    // Typing part of a name narrows the list.
    picker->completer()->setCompletionPrefix(QStringLiteral("lee"));
    QCOMPARE(picker->completer()->completionCount(), 1);
    QCOMPARE(picker->completer()->currentCompletion(), QStringLiteral("fleet — 0 includes"));

    QSignalSpy chosen(&panel, &DiagramPanel::rootChosen);
    QVERIFY(laidOut(panel, [&] { Q_EMIT picker->activated(0); }));
    QCOMPARE(chosen.size(), 1);
    QCOMPARE(chosen.first().first().toString(), QStringLiteral("lf1"));
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf1"));
    QVERIFY(panel.scene()->item(QStringLiteral("part:part1")));
    // Going down an include keeps the picker on its root; the breadcrumbs say the rest.
    QVERIFY(laidOut(panel, [&] { panel.showComposite(QStringLiteral("lf2")); }));
    QCOMPARE(picker->currentRoot(), QStringLiteral("lf1"));
    QCOMPARE(panel.breadcrumbIds(), (QStringList{"lf1", "lf2"}));
    QCOMPARE(chosen.size(), 1); // only a person's choice is reported
}

void TestDiagramNavigation::pickerFitsItsListsWhenTheyOpen()
{
    // Hundreds of roots (autoware's) are measured when a list opens, not with every result.
    const auto roots = [](int count, const QString &stem) {
        QList<LaunchRoot> out;
        for (int i = 0; i < count; ++i)
            out.append({QStringLiteral("lf%1").arg(i), stem.arg(i), {}, i, i, 0});
        return out;
    };
    const QString stem = QStringLiteral("a_rather_long_launch_file_name_number_%1");
    const QString longer = QStringLiteral("an_even_longer_launch_file_name_than_before_number_%1");
    for (const int count : {3, 300}) {
        DiagramRootPicker picker;
        picker.show();
        QVERIFY(QTest::qWaitForWindowExposed(&picker));
        picker.setRoots(roots(count, stem));
        QCOMPARE(picker.count(), count);
        const int fitted = picker.view()->sizeHintForColumn(0) + 24;
        QVERIFY2(fitted > picker.width(), "the entries are wider than the box");
        if (count <= 40) {
            QCOMPARE(picker.view()->minimumWidth(), fitted); // a few: at once
            continue;
        }
        QVERIFY(picker.view()->minimumWidth() < fitted);
        // Typing opens the completer's list: both lists fit then.
        QTest::keyClicks(picker.lineEdit(), QStringLiteral("number_29"));
        QCOMPARE(picker.view()->minimumWidth(), fitted);
        QCOMPARE(picker.completer()->popup()->minimumWidth(), fitted);
        picker.completer()->popup()->hide();
        // Longer names: measured again when the list opens.
        picker.setRoots(roots(count, longer));
        const int wider = picker.view()->sizeHintForColumn(0) + 24;
        QVERIFY(wider > fitted);
        QCOMPARE(picker.view()->minimumWidth(), fitted);
        picker.showPopup();
        QCOMPARE(picker.view()->minimumWidth(), wider);
        picker.hidePopup();
    }
}

void TestDiagramNavigation::askingListsTheRoots()
{
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(900, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setArchitecture(twoRoots(1), {}, RootChoice{{}, RootChoice::Reason::Ask});
    QVERIFY(panel.isAskingForRoot());
    QVERIFY(!panel.view()->isVisible());
    QVERIFY(panel.currentComposite().isEmpty());
    QListWidget *list = panel.rootPrompt()->list();
    QCOMPARE(list->count(), 2);
    QVERIFY(list->item(1)->text().startsWith(QLatin1String("fleet")));
    saveScreenshot(panel, QStringLiteral("diagram_root_prompt.png"));
    // Not modal: the picker in the header works as well; here the list is used.
    QVERIFY(panel.rootPicker()->isEnabled());
    QSignalSpy chosen(&panel, &DiagramPanel::rootChosen);
    QVERIFY(laidOut(panel, [&] {
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                          list->visualItemRect(list->item(1)).center());
    }));
    QCOMPARE(chosen.size(), 1);
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf9"));
    QVERIFY(!panel.isAskingForRoot());
    QVERIFY(panel.view()->isVisible());
    QCOMPARE(panel.rootPicker()->currentRoot(), QStringLiteral("lf9"));
}

void TestDiagramNavigation::tooBigStartsAsAnOverview()
{
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(900, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    Architecture arch;
    arch.composites << test::diagram::fleet(6);
    QVERIFY(laidOut(panel, [&] { panel.setArchitecture(arch); }));
    // The whole fleet at fit would be unreadable: one box per robot instead.
    QVERIFY(panel.isCollapsed());
    QVERIFY(panel.isNamespaceCollapsed(QStringLiteral("/robot1")));
    QVERIFY(panel.scene()->item(QStringLiteral("namespace:/robot6")));
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part2")));
    QVERIFY(namePixels(panel) >= legiblePixels(panel) - 0.01);
    QVERIFY(panel.expandAllAction()->isEnabled());
    saveScreenshot(panel, QStringLiteral("diagram_overview.png"));

    // Double-click a box: that robot opens, its parts still without port rows.
    DiagramNodeItem *box =
        dynamic_cast<DiagramNodeItem *>(panel.scene()->item(QStringLiteral("namespace:/robot1")));
    QVERIFY(box);
    panel.view()->centerOn(box);
    const QPoint at = panel.view()->mapFromScene(box->sceneBoundingRect().center());
    QVERIFY(laidOut(panel,
                    [&] { QTest::mouseDClick(panel.view()->viewport(), Qt::LeftButton, {}, at); }));
    QVERIFY(!panel.isNamespaceCollapsed(QStringLiteral("/robot1")));
    auto *driver =
        dynamic_cast<DiagramNodeItem *>(panel.scene()->item(QStringLiteral("part:part2")));
    QVERIFY(driver);
    QVERIFY(driver->node().ports.isEmpty());
    QVERIFY(panel.scene()->item(QStringLiteral("namespace:/robot2")));
    // The context menu collapses it again.
    bool collapsed = false;
    QVERIFY(laidOut(panel, [&] {
        for (QAction *a : panel.elementActions(QStringLiteral("part:part2")))
            if (a->text() == QLatin1String("Collapse Namespace /robot1")) {
                a->trigger();
                collapsed = true;
            }
    }));
    QVERIFY(collapsed);
    QVERIFY(panel.isNamespaceCollapsed(QStringLiteral("/robot1")));

    // Expand All: every part with its ports; fit stops at the legible size.
    QVERIFY(laidOut(panel, [&] { panel.expandAllAction()->trigger(); }));
    QVERIFY(!panel.isCollapsed());
    QVERIFY(panel.scene()->item(QStringLiteral("part:part2")));
    QVERIFY(!panel.scene()->item(QStringLiteral("namespace:/robot1")) ||
            !dynamic_cast<DiagramNodeItem *>(panel.scene()->item("namespace:/robot1")));
    QVERIFY(namePixels(panel) >= legiblePixels(panel) - 0.01);
    QVERIFY(panel.view()->fitZoom() < panel.view()->legibleZoom());
    // It starts where reading starts: the top left corner.
    const QRectF shown = panel.view()->mapToScene(panel.view()->viewport()->rect()).boundingRect();
    QVERIFY(qAbs(shown.top() - panel.scene()->sceneRect().top()) < 2);
    QVERIFY(qAbs(shown.left() - panel.scene()->sceneRect().left()) < 2);
    QVERIFY(panel.view()->minimap()->isVisible());
    // And back to the overview.
    QVERIFY(laidOut(panel, [&] { panel.overviewAction()->trigger(); }));
    QVERIFY(panel.isNamespaceCollapsed(QStringLiteral("/robot3")));
}

void TestDiagramNavigation::minimapShowsAndPans()
{
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(900, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    // A small diagram fits: no minimap.
    QVERIFY(laidOut(panel, [&] { panel.setArchitecture(test::diagram::architecture()); }));
    DiagramMinimap *minimap = panel.view()->minimap();
    QVERIFY(!minimap->isVisible());
    // Zoomed in, part of it is out of view: the minimap shows, with the view's rectangle.
    panel.view()->setZoom(2.5);
    QVERIFY(minimap->isVisible());
    const QRectF outline = minimap->viewportRect();
    QVERIFY(!outline.isEmpty());
    QVERIFY(outline.width() < minimap->width());
    // A click on the minimap's bottom-right corner moves the view there.
    const QRectF before = panel.view()->mapToScene(panel.view()->viewport()->rect()).boundingRect();
    const QPoint corner(minimap->width() - 6, minimap->height() - 6);
    QTest::mouseClick(minimap, Qt::LeftButton, {}, corner);
    const QRectF after = panel.view()->mapToScene(panel.view()->viewport()->rect()).boundingRect();
    QVERIFY(after.center().x() > before.center().x());
    QVERIFY(after.center().y() >= before.center().y());
    QVERIFY(after.adjusted(-2, -2, 2, 2).contains(minimap->toScene(QPointF(corner))) ||
            after.right() >= panel.scene()->sceneRect().right() - 2);
    // A drag pans as well.
    const QPointF centre = panel.view()->mapToScene(panel.view()->viewport()->rect().center());
    QTest::mousePress(minimap, Qt::LeftButton, {}, QPoint(8, 8));
    QMouseEvent move(QEvent::MouseMove, QPointF(12, 10), minimap->mapToGlobal(QPointF(12, 10)),
                     Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(minimap, &move);
    QTest::mouseRelease(minimap, Qt::LeftButton, {}, QPoint(12, 10));
    const QPointF moved = panel.view()->mapToScene(panel.view()->viewport()->rect().center());
    QVERIFY(moved.x() < centre.x());
    saveScreenshot(panel, QStringLiteral("diagram_minimap.png"));
    // Fit again: it all fits, the minimap goes.
    panel.view()->fitDiagram();
    QTRY_VERIFY(!minimap->isVisible()); // once the scroll bars have gone
}

void TestDiagramNavigation::fitStartsAtTheFirstBoxWhenTheCornerIsEmpty()
{
    // Before: too big to fit legibly, Fit showed the frame's top left corner, which a wide
    // layout (autoware's perception, expanded) leaves empty: a blank view.
    LayoutGraph graph;
    LayoutGeometry geometry;
    geometry.bounds = QRectF(0, 0, 4000, 3000);
    const std::pair<const char *, QRectF> boxes[] = {{"first", QRectF(1500, 1800, 120, 40)},
                                                     {"last", QRectF(3800, 2900, 120, 40)}};
    for (const auto &[id, rect] : boxes) {
        LayoutNode n;
        n.id = QString::fromLatin1(id);
        n.key = QStringLiteral("part:") + n.id;
        n.label = n.id;
        n.width = rect.width();
        n.height = rect.height();
        graph.nodes.append(n);
        geometry.nodes.insert(n.id, rect);
    }
    DiagramScene scene;
    scene.setDiagram(graph, geometry, QStringLiteral("wide"), QString());
    DiagramView view;
    view.setScene(&scene);
    view.resize(400, 300);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.setLegibleZoom(1.0);
    view.fitDiagram();
    QCOMPARE(view.zoom(), 1.0);
    const QRectF shown = view.mapToScene(view.viewport()->rect()).boundingRect();
    QVERIFY2(shown.contains(scene.item(QStringLiteral("part:first"))->sceneBoundingRect()),
             qPrintable(QStringLiteral("shown %1,%2 %3x%4")
                            .arg(shown.left())
                            .arg(shown.top())
                            .arg(shown.width())
                            .arg(shown.height())));

    // A box in sight of the corner: the corner it is, the frame's title with it.
    geometry.nodes.insert(QStringLiteral("first"), QRectF(60, 40, 120, 40));
    scene.setDiagram(graph, geometry, QStringLiteral("wide"), QString());
    view.fitDiagram();
    const QRectF corner = view.mapToScene(view.viewport()->rect()).boundingRect();
    QVERIFY(qAbs(corner.top() - scene.sceneRect().top()) < 2);
    QVERIFY(qAbs(corner.left() - scene.sceneRect().left()) < 2);
}

void TestDiagramNavigation::theFramesTabStaysInsideTheFrame()
{
    // Before: a narrow composite's tab ran past its frame with the launch file's whole path.
    LayoutGraph graph;
    LayoutNode n;
    n.id = QStringLiteral("only");
    n.key = QStringLiteral("part:only");
    n.label = n.id;
    graph.nodes.append(n);
    LayoutGeometry geometry;
    geometry.bounds = QRectF(0, 0, 260, 80);
    geometry.nodes.insert(n.id, QRectF(20, 20, 80, 36));
    const QString detail =
        QStringLiteral("launch file nav2_bringup/launch/unique_multi_tb3_simulation_launch.py");
    DiagramScene scene;
    scene.setDiagram(graph, geometry, QStringLiteral("unique_multi_tb3_simulation"), detail);
    const DiagramClusterItem *frame = nullptr;
    for (QGraphicsItem *item : scene.items())
        if (auto *c = dynamic_cast<const DiagramClusterItem *>(item);
            c && c->kind() == DiagramClusterItem::Kind::Frame)
            frame = c;
    QVERIFY(frame);
    const DiagramClusterItem::Tab tab = frame->tab();
    QVERIFY2(tab.width <= scene.frameRect().width(),
             qPrintable(QStringLiteral("%1 > %2").arg(tab.width).arg(scene.frameRect().width())));
    QVERIFY(tab.detail.isEmpty() || tab.detail.endsWith(QStringLiteral(".py")));
    QVERIFY(tab.detail != detail);
    // Wide enough: all of it.
    geometry.bounds = QRectF(0, 0, 1200, 80);
    scene.setDiagram(graph, geometry, QStringLiteral("unique_multi_tb3_simulation"), detail);
    for (QGraphicsItem *item : scene.items())
        if (auto *c = dynamic_cast<const DiagramClusterItem *>(item);
            c && c->kind() == DiagramClusterItem::Kind::Frame)
            QCOMPARE(c->tab().detail, detail);
}

void TestDiagramNavigation::pickerListsRootsByName()
{
    // Before: in the analysis' order (by path), which the list, showing names, did not show.
    DiagramRootPicker picker;
    picker.setRoots(
        {{QStringLiteral("lf1"), QStringLiteral("zeta"), QStringLiteral("a/zeta.xml")},
         {QStringLiteral("lf2"), QStringLiteral("Alpha"), QStringLiteral("z/Alpha.xml")},
         {QStringLiteral("lf3"), QStringLiteral("beta"), QStringLiteral("m/beta.xml")}});
    QStringList shown;
    for (int i = 0; i < picker.count(); ++i)
        shown << picker.itemData(i).toString();
    QCOMPARE(shown, (QStringList{"lf2", "lf3", "lf1"}));
    picker.setCurrentRoot(QStringLiteral("lf1"));
    QCOMPARE(picker.currentRoot(), QStringLiteral("lf1"));
    // An executable that builds its own nodes includes nothing: it says what it is.
    LaunchRoot exe{QStringLiteral("lf4"), QStringLiteral("manual_composition"),
                   QStringLiteral("src/composition/src/manual_composition.cpp")};
    exe.nodes = 4;
    exe.executable = true;
    QCOMPARE(DiagramRootPicker::entryText(exe),
             QStringLiteral("manual_composition — executable, 4 nodes"));
}

QTEST_MAIN(TestDiagramNavigation)
#include "tst_diagramnavigation.moc"
