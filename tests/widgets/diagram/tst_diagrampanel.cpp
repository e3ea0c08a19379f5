#include "diagram/diagramlayouter.h"
#include "support/diagramarchitecture.h"
#include "support/diagramshownpanel.h"
#include "support/diagramwait.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/diagram/diagrambreadcrumbbar.h"
#include "widgets/diagram/diagramclusteritem.h"
#include "widgets/diagram/diagramedgeitem.h"
#include "widgets/diagram/diagramminimap.h"
#include "widgets/diagram/diagramnodeitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramtext.h"
#include "widgets/diagram/diagramview.h"

#include <QAction>
#include <QFile>
#include <QImage>
#include <QLineEdit>
#include <QScrollBar>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace rosarch;
using rosarch::test::laidOut;
using rosarch::test::saveScreenshot;
using rosarch::test::ShownPanel;

namespace {

DiagramNodeItem *nodeItem(DiagramPanel &panel, const QString &key)
{
    return dynamic_cast<DiagramNodeItem *>(panel.scene()->item(key));
}

/// A point on a node's title, in viewport coordinates.
QPoint titlePoint(DiagramPanel &panel, const QString &key)
{
    DiagramNodeItem *item = nodeItem(panel, key);
    if (!item)
        return {};
    panel.view()->centerOn(item);
    return panel.view()->mapFromScene(item->mapToScene(QPointF(item->node().width / 2, 12)));
}

QPoint scenePoint(DiagramPanel &panel, const QPointF &p)
{
    panel.view()->centerOn(p);
    return panel.view()->mapFromScene(p);
}

} // namespace

class TestDiagramPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void drawsTheRootComposite();
    void searchFindsParts();
    void doubleClickOpensTheIncludeAndCrumbsGoBack();
    void aDeepPathDoesNotWidenThePanel();
    void filtersHideElements();
    void collapseReducesANamespaceToOneBox();
    void clicksCarryIds();
    void selectInstanceCentresThePart();
    void marksAndMissingBanner();
    void toolTipsSayWhatIsAGuess();
    void exportsSvgAndPng();
    void layoutFailuresAreShownInTheView();
    void staleLayoutsAreDropped();
    void zoomKeys();
    void biggerDiagram();
};

void TestDiagramPanel::drawsTheRootComposite()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    qInfo("root composite laid out in %lld ms", panel.lastLayoutMs());
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf1"));
    QCOMPARE(panel.breadcrumbIds(), QStringList{QStringLiteral("lf1")});
    QVERIFY(panel.message().isEmpty());
    const QStringList keys = panel.scene()->keys();
    for (const char *key :
         {"part:part1", "part:part2", "part:part3", "part:part4", "part:part5", "channel:q_chatter",
          "channel:c_reset", "channel:a_navigate", "boundary:s1", "boundary:p1",
          "namespace:/robot1", "namespace:/robot1/extra", "connection:0", "connection:7"})
        QVERIFY2(keys.contains(QLatin1String(key)), key);
    QCOMPARE(keys.size(), 5 + 3 + 2 + 2 + 8);
    QVERIFY(dynamic_cast<DiagramClusterItem *>(
        panel.scene()->item(QStringLiteral("namespace:/robot1"))));
    // Nodes do not overlap; namespaces hold their parts; boundary ports sit on the frame.
    QList<QRectF> rects;
    for (const QString &key : keys)
        if (DiagramNodeItem *n = nodeItem(panel, key))
            rects << n->mapRectToScene(QRectF(0, 0, n->node().width, n->node().height));
    for (int i = 0; i < rects.size(); ++i)
        for (int j = i + 1; j < rects.size(); ++j)
            QVERIFY(!rects[i].intersects(rects[j]));
    QVERIFY(panel.scene()
                ->item(QStringLiteral("namespace:/robot1"))
                ->sceneBoundingRect()
                .contains(nodeItem(panel, QStringLiteral("part:part4"))->sceneBoundingRect()));
    const QRectF frame = panel.scene()->frameRect();
    DiagramNodeItem *in = nodeItem(panel, QStringLiteral("boundary:s1"));
    QVERIFY(std::abs(in->mapRectToScene(in->rect()).left() - frame.left()) < 0.5);
    DiagramNodeItem *out = nodeItem(panel, QStringLiteral("boundary:p1"));
    QVERIFY(std::abs(out->mapRectToScene(out->rect()).right() - frame.right()) < 0.5);
    // Inactive and unresolved are carried to the drawing.
    QVERIFY(nodeItem(panel, QStringLiteral("part:part3"))->node().flags & LayoutInactive);
    // Tooltips say what a thing is and where it comes from.
    QVERIFY(panel.scene()
                ->toolTip(QStringLiteral("port:part1/s1"))
                .contains(QLatin1String("talker.py:12")));
    saveScreenshot(panel, QStringLiteral("diagram_root.png"));

    QPalette dark = panel.palette();
    dark.setColor(QPalette::Window, QColor(0x2b, 0x2b, 0x2b));
    dark.setColor(QPalette::WindowText, Qt::white);
    dark.setColor(QPalette::Base, QColor(0x1e, 0x1e, 0x1e));
    dark.setColor(QPalette::Text, Qt::white);
    dark.setColor(QPalette::Button, QColor(0x35, 0x35, 0x35));
    dark.setColor(QPalette::ButtonText, Qt::white);
    panel.setPalette(dark);
    QVERIFY(panel.scene()->diagramStyle().dark);
    saveScreenshot(panel, QStringLiteral("diagram_root_dark.png"));
}

void TestDiagramPanel::searchFindsParts()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    panel.searchField()->setText(QStringLiteral("navig"));
    const QStringList matched = {QStringLiteral("part:part4"),
                                 QStringLiteral("channel:a_navigate")};
    for (const QString &key : matched)
        QVERIFY(panel.scene()->item(key)->isMatched());
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part1"))->isMatched());
    QList<QGraphicsItem *> selected = panel.scene()->selectedItems();
    QCOMPARE(selected.size(), 1);
    const QString first = dynamic_cast<DiagramItem *>(selected.first())->key();
    QVERIFY(matched.contains(first));
    QTest::keyClick(panel.searchField(), Qt::Key_Return);
    selected = panel.scene()->selectedItems();
    QCOMPARE(selected.size(), 1);
    const QString second = dynamic_cast<DiagramItem *>(selected.first())->key();
    QVERIFY(matched.contains(second));
    QVERIFY(second != first);
    QCOMPARE(panel.matchText(), QStringLiteral("2 of 2")); // a count, and where
    saveScreenshot(panel, QStringLiteral("diagram_search.png"));
    QTest::keyClick(panel.searchField(), Qt::Key_Return); // wraps around
    QCOMPARE(dynamic_cast<DiagramItem *>(panel.scene()->selectedItems().first())->key(), first);
    // Namespaces are found too; nothing matches nonsense.
    panel.searchField()->setText(QStringLiteral("extra"));
    QVERIFY(panel.scene()->item(QStringLiteral("namespace:/robot1/extra"))->isMatched());
    panel.searchField()->setText(QStringLiteral("zzz"));
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part4"))->isMatched());
    QCOMPARE(panel.matchText(), QStringLiteral("No match"));
    panel.searchField()->clear();
    QCOMPARE(panel.matchText(), QString());
}

void TestDiagramPanel::aDeepPathDoesNotWidenThePanel()
{
    // Before: the breadcrumbs' width was the panel's minimum, so opening an include with a
    // long path and note (nav2's tb3_simulation) widened the diagram's dock and squeezed the
    // panes beside it.
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    const int before = panel.minimumSizeHint().width();
    QList<DiagramBreadcrumbBar::Crumb> path;
    for (int i = 0; i < 4; ++i)
        path.append({QStringLiteral("lf%1").arg(i),
                     QStringLiteral("unique_multi_tb3_simulation_%1").arg(i), QString()});
    panel.breadcrumbBar()->setPath(
        path, QStringLiteral("as included by unique_multi_tb3_simulation_launch.py"), QString());
    QTRY_VERIFY(panel.breadcrumbBar()->sizeHint().width() > 800); // it would want that much
    QVERIFY2(panel.minimumSizeHint().width() <= std::max(before, 400),
             qPrintable(QString::number(panel.minimumSizeHint().width())));
}

void TestDiagramPanel::doubleClickOpensTheIncludeAndCrumbsGoBack()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    QSignalSpy shown(&panel, &DiagramPanel::compositeShown);
    QVERIFY(laidOut(panel, [&] {
        QTest::mouseDClick(panel.view()->viewport(), Qt::LeftButton, {},
                           titlePoint(panel, QStringLiteral("part:part2")));
    }));
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf2"));
    QCOMPARE(shown.size(), 1);
    QCOMPARE(shown.first().first().toString(), QStringLiteral("lf2"));
    QCOMPARE(panel.breadcrumbIds(), QStringList({QStringLiteral("lf1"), QStringLiteral("lf2")}));
    QCOMPARE(panel.breadcrumbBar()->button(QStringLiteral("lf1"))->text(), QStringLiteral("demo"));
    QCOMPARE(panel.breadcrumbBar()->button(QStringLiteral("lf2"))->text(),
             QStringLiteral("listener"));
    QVERIFY(panel.scene()->item(QStringLiteral("boundary:ps1")));
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part5")));
    QVERIFY(nodeItem(panel, QStringLiteral("part:part1"))->node().ports[2].flags &
            LayoutUnresolved);
    saveScreenshot(panel, QStringLiteral("diagram_child.png"));

    QVERIFY(laidOut(panel, [&] {
        QTest::mouseClick(panel.breadcrumbBar()->button(QStringLiteral("lf1")), Qt::LeftButton);
    }));
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf1"));
    QCOMPARE(panel.breadcrumbIds(), QStringList{QStringLiteral("lf1")});
    QCOMPARE(shown.last().first().toString(), QStringLiteral("lf1"));
    QVERIFY(panel.scene()->item(QStringLiteral("part:part5")));
    // The external include has no diagram of its own: double-click leaves the view alone.
    QTest::mouseDClick(panel.view()->viewport(), Qt::LeftButton, {},
                       titlePoint(panel, QStringLiteral("part:part5")));
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf1"));
}

void TestDiagramPanel::filtersHideElements()
{
    ShownPanel s(true);
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    // Inactive parts and ports are hidden at first; the toggle shows them and hides them again.
    QVERIFY(!panel.showInactiveAction()->isChecked());
    QVERIFY(!panel.options().showInactive);
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part3")));
    QVERIFY(!panel.scene()->item(QStringLiteral("namespace:/robot1/extra")));
    QVERIFY(!panel.scene()->item(QStringLiteral("boundary:p1")));
    QVERIFY(panel.scene()->item(QStringLiteral("part:part1")));
    QVERIFY(laidOut(panel, [&] { panel.showInactiveAction()->trigger(); }));
    QVERIFY(panel.scene()->item(QStringLiteral("part:part3")));
    QVERIFY(laidOut(panel, [&] { panel.showInactiveAction()->trigger(); }));
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part3")));
    QVERIFY(laidOut(panel, [&] { panel.showInactiveAction()->trigger(); }));

    QVERIFY(laidOut(panel, [&] { panel.showParametersAction()->trigger(); }));
    QCOMPARE(nodeItem(panel, QStringLiteral("part:part1"))->node().ports.size(), 3);
    QVERIFY(!panel.scene()->item(QStringLiteral("boundary:s1")));
    QVERIFY(!panel.scene()->item(QStringLiteral("connection:6")));
    QVERIFY(!panel.options().showParameterPorts);

    QVERIFY(laidOut(panel, [&] { panel.showExternalAction()->trigger(); }));
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part5")));
    QVERIFY(panel.scene()->item(QStringLiteral("part:part2")));
}

void TestDiagramPanel::collapseReducesANamespaceToOneBox()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    const QList<QAction *> actions = panel.elementActions(QStringLiteral("namespace:/robot1"));
    QCOMPARE(actions.size(), 1);
    QCOMPARE(actions.first()->text(), QStringLiteral("Collapse Namespace /robot1"));
    QVERIFY(laidOut(panel, [&] { actions.first()->trigger(); }));
    QVERIFY(panel.isNamespaceCollapsed(QStringLiteral("/robot1")));
    for (const char *gone : {"part:part2", "part:part3", "part:part4", "namespace:/robot1/extra"})
        QVERIFY2(!panel.scene()->item(QLatin1String(gone)), gone);
    DiagramNodeItem *box = nodeItem(panel, QStringLiteral("namespace:/robot1"));
    QVERIFY(box);
    QCOMPARE(box->node().shape, LayoutNode::Shape::Folder);
    int attached = 0;
    for (QGraphicsItem *item : panel.scene()->items())
        if (auto *e = dynamic_cast<DiagramEdgeItem *>(item))
            attached += e->edge().head == box->key() || e->edge().tail == box->key();
    QCOMPARE(attached, 4);
    QCOMPARE(panel.elementActions(box->key()).first()->text(),
             QStringLiteral("Expand Namespace /robot1"));
    QVERIFY(panel.selectInstance(QStringLiteral("n5"))); // its part is inside the box
    QVERIFY(box->isSelected());
    saveScreenshot(panel, QStringLiteral("diagram_collapsed.png"));

    // Double-click on the box expands it again.
    QVERIFY(laidOut(panel, [&] {
        QTest::mouseDClick(panel.view()->viewport(), Qt::LeftButton, {},
                           titlePoint(panel, QStringLiteral("namespace:/robot1")));
    }));
    QVERIFY(!panel.isNamespaceCollapsed(QStringLiteral("/robot1")));
    QVERIFY(panel.scene()->item(QStringLiteral("part:part4")));
}

void TestDiagramPanel::clicksCarryIds()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    QSignalSpy parts(&panel, &DiagramPanel::partActivated);
    QSignalSpy ports(&panel, &DiagramPanel::portActivated);
    QSignalSpy evidence(&panel, &DiagramPanel::evidenceActivated);

    const QPoint title = titlePoint(panel, QStringLiteral("part:part1"));
    QCOMPARE(panel.scene()->keyAt(panel.view()->mapToScene(title)), QStringLiteral("part:part1"));
    QTest::mouseClick(panel.view()->viewport(), Qt::LeftButton, {}, title);
    QCOMPARE(parts.size(), 1);
    QCOMPARE(parts.first().first().toString(), QStringLiteral("n1"));
    QCOMPARE(evidence.size(), 1);
    QCOMPARE(evidence.last().first().value<Evidence>().line, 18);

    DiagramNodeItem *talker = nodeItem(panel, QStringLiteral("part:part1"));
    const QPointF s1 = talker->portScenePos(QStringLiteral("s1")) + QPointF(20, 0);
    QCOMPARE(panel.scene()->keyAt(s1), QStringLiteral("port:part1/s1"));
    QTest::mouseClick(panel.view()->viewport(), Qt::LeftButton, {}, scenePoint(panel, s1));
    QCOMPARE(ports.size(), 1);
    QCOMPARE(ports.first().at(0).toString(), QStringLiteral("n1"));
    QCOMPARE(ports.first().at(1).toString(), QStringLiteral("s1"));
    QCOMPARE(evidence.last().first().value<Evidence>().line, 12);

    auto *edge =
        dynamic_cast<DiagramEdgeItem *>(panel.scene()->item(QStringLiteral("connection:0")));
    QVERIFY(edge);
    const QPointF middle = edge->path().pointAtPercent(0.5);
    QCOMPARE(panel.scene()->keyAt(middle), QStringLiteral("connection:0"));
    QTest::mouseClick(panel.view()->viewport(), Qt::LeftButton, {}, scenePoint(panel, middle));
    QCOMPARE(evidence.size(), 3);
    const Evidence e = evidence.last().first().value<Evidence>();
    QCOMPARE(e.file, QStringLiteral("src/demo/demo/talker.py"));
    QCOMPARE(e.line, 11); // the publisher p1
    // The edge stands for its part's port: the part is activated (the other views follow it)
    // and selected with the edge once the click ends.
    QCOMPARE(parts.size(), 2);
    QCOMPARE(parts.last().first().toString(), QStringLiteral("n1"));
    QVERIFY(edge->isSelected());
    QVERIFY(talker->isSelected());
    QCOMPARE(panel.scene()->selectedItems().size(), 2);
}

void TestDiagramPanel::selectInstanceCentresThePart()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    panel.resize(420, 320);
    QTest::qWait(50); // the layout hands the view its new size
    panel.view()->setZoom(1.0);
    QVERIFY(panel.selectInstance(QStringLiteral("n5")));
    DiagramItem *navigator = panel.scene()->item(QStringLiteral("part:part4"));
    QVERIFY(navigator->isSelected());
    QCOMPARE(panel.scene()->selectedItems().size(), 1);
    const QPoint centre = panel.view()->mapFromScene(navigator->sceneBoundingRect().center());
    QVERIFY(panel.view()->viewport()->rect().contains(centre));
    QVERIFY(panel.selectInstance(QStringLiteral("n1")));
    QVERIFY(!navigator->isSelected());
    QVERIFY(!panel.selectInstance(QStringLiteral("n2"))); // in the child composite only
}

void TestDiagramPanel::marksAndMissingBanner()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    panel.setMarks({{QStringLiteral("part:part1"), DiagramMark::Extra},
                    {QStringLiteral("channel:c_reset"), DiagramMark::Extra}},
                   {QStringLiteral("part ghost"), QStringLiteral("topic /ghost"),
                    QStringLiteral("service /x")});
    QCOMPARE(panel.scene()->item(QStringLiteral("part:part1"))->mark(), DiagramMark::Extra);
    QCOMPARE(panel.scene()->item(QStringLiteral("part:part2"))->mark(), DiagramMark::None);
    QCOMPARE(panel.view()->banner(),
             QStringLiteral("3 elements of the reference are missing: part ghost, topic /ghost, "
                            "service /x"));
    // Marks survive a re-layout of the same composite, and go with another composite.
    QVERIFY(laidOut(panel, [&] { panel.showExternalAction()->trigger(); }));
    QCOMPARE(panel.scene()->item(QStringLiteral("channel:c_reset"))->mark(), DiagramMark::Extra);
    saveScreenshot(panel, QStringLiteral("diagram_marks.png"));
    QVERIFY(laidOut(panel, [&] { panel.showComposite(QStringLiteral("lf2")); }));
    QVERIFY(panel.view()->banner().isEmpty());
    QCOMPARE(panel.scene()->item(QStringLiteral("part:part1"))->mark(), DiagramMark::None);
}

// A name built on a guessed launch value says so where the person points at it: a port remapped
// onto a guess, a port under a guessed namespace, and a boundary port they are promoted to.
void TestDiagramPanel::toolTipsSayWhatIsAGuess()
{
    Composite c = test::diagram::architecture().composites[0];
    QVERIFY(c.parts.size() > 0 && c.parts[0].ports.size() > 1 && !c.boundary.isEmpty());
    c.parts[0].ports[0].guessed = true;
    c.parts[0].ports[0].remapped = true;
    c.parts[0].ports[1].guessed = true;
    c.parts[0].ports[1].remapped = false;
    c.boundary[0].guessed = true;
    const QHash<QString, QString> tips = DiagramText::toolTips(c);
    const QString part = c.parts[0].id;
    QVERIFY(tips.value(DiagramBuilder::portKey(part, c.parts[0].ports[0].id))
                .contains(QStringLiteral("Remapped to a name built from a launch value")));
    QVERIFY(tips.value(DiagramBuilder::portKey(part, c.parts[0].ports[1].id))
                .contains(QStringLiteral("Its namespace or node name is built from a launch")));
    QVERIFY(tips.value(DiagramBuilder::boundaryKey(c.boundary[0].id))
                .contains(QStringLiteral("it is a guess")));
    if (c.boundary.size() > 1)
        QVERIFY(!tips.value(DiagramBuilder::boundaryKey(c.boundary[1].id))
                     .contains(QStringLiteral("guess")));
    // A port of code outside the workspace names its interface model and the launch line.
    Composite modelled = test::diagram::architecture().composites[0];
    modelled.parts[0].typed = false;
    modelled.parts[0].ports[0].model = QStringLiteral("robot_state_publisher");
    modelled.parts[0].ports[0].evidence = {QStringLiteral("src/b/launch/b.launch.py"), 12, 5, 12,
                                           40};
    const QHash<QString, QString> modelledTips = DiagramText::toolTips(modelled);
    const QString portTip =
        modelledTips.value(DiagramBuilder::portKey(part, modelled.parts[0].ports[0].id));
    QVERIFY2(portTip.contains(QStringLiteral("From the interface model robot_state_publisher (code "
                                             "outside the workspace), started at "
                                             "src/b/launch/b.launch.py:12")),
             qPrintable(portTip));
    QVERIFY(!portTip.contains(QStringLiteral("Created at")));
    QVERIFY(modelledTips.value(DiagramBuilder::partKey(part))
                .contains(QStringLiteral("its ports come from an interface model")));
}

void TestDiagramPanel::exportsSvgAndPng()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    QTemporaryDir dir;
    const QString svgPath = dir.filePath(QStringLiteral("demo.svg"));
    const QString pngPath = dir.filePath(QStringLiteral("demo.png"));
    QVERIFY(panel.exportSvg(svgPath));
    QVERIFY(panel.exportPng(pngPath));
    const QByteArray svg = test::readFile(svgPath);
    QVERIFY(svg.contains("<svg"));
    QVERIFY(svg.contains("</svg>"));
    for (const char *text : {"talker", "listener", "navigator", "/chatter", "/robot1", "demo"})
        QVERIFY2(svg.contains(text), text);
    const QImage png(pngPath);
    QVERIFY(!png.isNull());
    const QRectF scene = panel.scene()->sceneRect();
    QCOMPARE(png.width(), qRound(scene.width() * 2));
    QVERIFY(std::abs(double(png.width()) / png.height() - scene.width() / scene.height()) < 0.02);
    QCOMPARE(png.pixelColor(2, 2), QColor(Qt::white)); // light paper whatever the screen
    const QString shots = qEnvironmentVariable("ROSARCH_SCREENSHOT_DIR");
    if (!shots.isEmpty())
        panel.exportPng(QDir(shots).filePath(QStringLiteral("diagram_export.png")));

    DiagramLayouter layouter;
    DiagramPanel empty(&layouter);
    QVERIFY(!empty.exportSvg(dir.filePath(QStringLiteral("none.svg"))));
    QVERIFY(!empty.message().isEmpty());
}

void TestDiagramPanel::layoutFailuresAreShownInTheView()
{
    QTemporaryDir dir;
    qputenv("ROSARCH_LAYOUT",
            test::script(dir, QStringLiteral("abort.sh"), "kill -ABRT $$").toLocal8Bit());
    {
        DiagramLayouter layouter;
        DiagramPanel panel(&layouter);
        panel.resize(800, 500);
        panel.show();
        QSignalSpy finished(&panel, &DiagramPanel::layoutFinished);
        QVERIFY(laidOut(panel, [&] { panel.setArchitecture(test::diagram::architecture()); }));
        QCOMPARE(finished.last().first().toBool(), false);
        QVERIFY2(panel.message().startsWith(
                     QLatin1String("Graphviz crashed (signal 6) on this diagram")),
                 qPrintable(panel.message()));
        QVERIFY(panel.scene()->keys().isEmpty());
        saveScreenshot(panel, QStringLiteral("diagram_error.png"));
    }
    qputenv("ROSARCH_LAYOUT",
            test::script(dir, QStringLiteral("slow.sh"), "exec sleep 30").toLocal8Bit());
    {
        DiagramLayouter layouter;
        layouter.setTimeout(300);
        DiagramPanel panel(&layouter);
        QSignalSpy finished(&panel, &DiagramPanel::layoutFinished);
        panel.setArchitecture(test::diagram::architecture());
        QVERIFY(panel.isLayingOut());
        QCOMPARE(panel.view()->busyText(), QStringLiteral("Laying out…"));
        QVERIFY(finished.wait(10000));
        QVERIFY(panel.message().startsWith(QLatin1String("Graphviz did not finish within 0.3 s")));
        QVERIFY(panel.view()->busyText().isEmpty());
    }
    qunsetenv("ROSARCH_LAYOUT");
}

void TestDiagramPanel::staleLayoutsAreDropped()
{
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    QSignalSpy finished(&panel, &DiagramPanel::layoutFinished);
    QSignalSpy shown(&panel, &DiagramPanel::compositeShown);
    panel.setArchitecture(test::diagram::architecture()); // lf1, in the background
    panel.showComposite(QStringLiteral("lf2"));           // supersedes it
    while (panel.isLayingOut())
        QVERIFY(finished.wait(30000));
    QTest::qWait(50);
    QCOMPARE(finished.size(), 1);
    QCOMPARE(shown.size(), 2);
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf2"));
    QVERIFY(panel.scene()->item(QStringLiteral("boundary:ps1")));
    QVERIFY(!panel.scene()->item(QStringLiteral("part:part5")));
}

void TestDiagramPanel::zoomKeys()
{
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramView *view = s.panel.view();
    view->setZoom(1.0);
    QTest::keyClick(view, Qt::Key_Plus);
    QVERIFY(view->zoom() > 1.1);
    QTest::keyClick(view, Qt::Key_Minus);
    QTest::keyClick(view, Qt::Key_Minus);
    QVERIFY(view->zoom() < 0.9);
    QTest::keyClick(view, Qt::Key_0);
    QVERIFY(view->zoom() <= 1.0);
    const QRectF visible = view->mapToScene(view->viewport()->rect()).boundingRect();
    QVERIFY(visible.adjusted(-2, -2, 2, 2).contains(s.panel.scene()->frameRect()));
}

void TestDiagramPanel::biggerDiagram()
{
    Architecture arch;
    arch.composites << test::diagram::fleet(3);
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(1280, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(laidOut(panel, [&] { panel.setArchitecture(arch); }));
    qInfo("fleet(3) laid out in %lld ms", panel.lastLayoutMs());
    QVERIFY(panel.message().isEmpty());
    QCOMPARE(panel.breadcrumbIds(), QStringList{QStringLiteral("lf9")});
    // Too big to read whole at 1280×800: it starts as the overview; expanded, all of it.
    QVERIFY(panel.isCollapsed());
    QVERIFY(laidOut(panel, [&] { panel.expandAll(); }));
    QVERIFY(panel.scene()->item(QStringLiteral("namespace:/robot3/sensors")));
    saveScreenshot(panel, QStringLiteral("diagram_fleet.png"));
    const QString shots = qEnvironmentVariable("ROSARCH_SCREENSHOT_DIR");
    if (!shots.isEmpty())
        QVERIFY(panel.exportPng(QDir(shots).filePath(QStringLiteral("diagram_fleet_export.png"))));
    // Searching a name shared by several parts finds each of them, in reading order.
    panel.searchField()->setText(QStringLiteral("planner"));
    int matched = 0;
    for (const QString &key : panel.scene()->keys())
        matched += panel.scene()->item(key)->isMatched();
    QCOMPARE(matched, 3);
}

QTEST_MAIN(TestDiagramPanel)
#include "tst_diagrampanel.moc"
