// The first view of a system shows its nodes: only what cannot be read at the legible zoom is
// collapsed, the boundary first, then the parts' port rows, then the biggest namespaces one at
// a time; and a box expanded by a double-click opens in place, in view.
#include "diagram/diagramlayouter.h"
#include "diagram/diagramoverview.h"
#include "support/diagramarchitecture.h"
#include "support/diagramwait.h"
#include "support/screenshot.h"
#include "widgets/diagram/diagramclusteritem.h"
#include "widgets/diagram/diagramfirstview.h"
#include "widgets/diagram/diagramnodeitem.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"

#include <QtTest>

using namespace rosarch;
using rosarch::test::laidOut;
using rosarch::test::saveScreenshot;

namespace {

Architecture fleet(int robots)
{
    Architecture arch;
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

QRectF shownRect(DiagramPanel &panel)
{
    return panel.view()->mapToScene(panel.view()->viewport()->rect()).boundingRect();
}

/// The parts drawn as boxes of their own.
QStringList drawnParts(DiagramPanel &panel)
{
    QStringList parts;
    for (const QString &key : panel.scene()->keys())
        if (key.startsWith(QLatin1String("part:")) &&
            dynamic_cast<DiagramNodeItem *>(panel.scene()->item(key)))
            parts << key;
    return parts;
}

} // namespace

class TestDiagramFirstView : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void stepsGoFromAllToTheOverview();
    void firstViewShowsNodes_data();
    void firstViewShowsNodes();
    void expandInPlaceKeepsThePartInView();
    void aRootOfIncludesOpensWhereItsNodesAre();
};

void TestDiagramFirstView::stepsGoFromAllToTheOverview()
{
    const Composite c = test::diagram::fleet(3);
    const QList<DiagramOptions> steps = DiagramFirstView::steps(c, DiagramOptions());
    QCOMPARE(steps.size(), 6); // all, boundary, ports, then /robot3, /robot2, /robot1
    QVERIFY(!steps[0].collapseBoundary && steps[0].compactParts.isEmpty());
    QVERIFY(steps[1].collapseBoundary && steps[1].compactParts.isEmpty());
    QCOMPARE(steps[2].compactParts.size(), c.parts.size());
    QVERIFY(steps[2].collapsedNamespaces.isEmpty());
    QCOMPARE(steps[3].collapsedNamespaces, QStringList{QStringLiteral("/robot3")});
    QCOMPARE(steps[4].collapsedNamespaces, (QStringList{"/robot2", "/robot3"}));
    QVERIFY(DiagramFirstView::sameCollapse(steps.last(),
                                           DiagramOverview::options(c, DiagramOptions())));
    QCOMPARE(DiagramFirstView::indexOf(steps, steps[4]), 4);
}

void TestDiagramFirstView::firstViewShowsNodes_data()
{
    QTest::addColumn<int>("robots");
    QTest::addColumn<QSize>("size");
    QTest::addColumn<int>("open");       // robots whose namespace is drawn open, at least
    QTest::addColumn<bool>("withPorts"); // every part drawn with its port rows
    QTest::newRow("fleet of 1, 1600x1000, all of it") << 1 << QSize(1600, 1000) << 1 << true;
    QTest::newRow("fleet of 2, 1100x720, every node") << 2 << QSize(1100, 720) << 2 << false;
    QTest::newRow("fleet of 3, 1280x800, every node") << 3 << QSize(1280, 800) << 3 << false;
    QTest::newRow("fleet of 4, 1400x900, one robot closed") << 4 << QSize(1400, 900) << 3 << false;
    QTest::newRow("fleet of 6, 1900x1050, two robots open") << 6 << QSize(1900, 1050) << 2 << false;
    QTest::newRow("fleet of 12, 900x600, the overview") << 12 << QSize(900, 600) << 0 << false;
}

void TestDiagramFirstView::firstViewShowsNodes()
{
    QFETCH(int, robots);
    QFETCH(QSize, size);
    QFETCH(int, open);
    QFETCH(bool, withPorts);
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(size);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    const Architecture arch = fleet(robots);
    QVERIFY(laidOut(panel, [&] { panel.setArchitecture(arch); }));
    saveScreenshot(panel, QStringLiteral("diagram_first_view_%1.png").arg(robots));
    // Whatever it draws, it draws legibly.
    QVERIFY(namePixels(panel) >= legiblePixels(panel) - 0.01);
    // The robots' namespaces are collapsed the last first, and only as many as do not fit:
    // the open ones show their four nodes each.
    int opened = 0;
    for (int r = 1; r <= robots; ++r) {
        const bool collapsed = panel.isNamespaceCollapsed(QStringLiteral("/robot%1").arg(r));
        QVERIFY2(collapsed || opened == r - 1, qPrintable(QStringLiteral("robot %1").arg(r)));
        opened += collapsed ? 0 : 1;
    }
    QVERIFY2(opened >= open, qPrintable(QStringLiteral("%1 robots open").arg(opened)));
    const QStringList parts = drawnParts(panel);
    QCOMPARE(parts.size(), 2 + 4 * opened); // map server, fleet monitor and each open robot's
    if (opened == robots) {
        // Every node fits: nothing is drawn smaller than it can be read.
        QVERIFY(panel.view()->fitZoom() >= panel.view()->legibleZoom());
        QVERIFY(panel.scene()->frameRect().isValid());
        QVERIFY(shownRect(panel).adjusted(-2, -2, 2, 2).contains(panel.scene()->frameRect()));
    }
    QCOMPARE(!panel.isPartCompact(QStringLiteral("part2")), withPorts);
    QCOMPARE(!panel.isCollapsed(), withPorts);
}

namespace {

/// Moves the view so that `key`'s box is in its bottom right corner, then double-clicks it
/// and waits for the drawing: where an expanded box is most easily pushed out of view.
bool expandFromTheCorner(DiagramPanel &panel, const QString &key)
{
    QGraphicsItem *box = panel.scene()->item(key);
    if (!box)
        return false;
    DiagramView *view = panel.view();
    const QRectF shown = shownRect(panel);
    const QPointF margin(12 / view->zoom(), 12 / view->zoom());
    view->centerOn(box->sceneBoundingRect().bottomRight() + margin -
                   (shown.bottomRight() - shown.center()));
    if (!shownRect(panel).contains(box->sceneBoundingRect()))
        return false;
    const QPoint at = view->mapFromScene(box->sceneBoundingRect().center());
    return laidOut(panel, [&] { QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, at); });
}

} // namespace

void TestDiagramFirstView::expandInPlaceKeepsThePartInView()
{
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(900, 600);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(laidOut(panel, [&] { panel.setArchitecture(fleet(6)); }));
    QVERIFY(panel.isNamespaceCollapsed(QStringLiteral("/robot4")));
    const qreal zoom = panel.view()->zoom();

    // A namespace: its frame opens where the box was and shows whole, with its parts.
    QVERIFY(expandFromTheCorner(panel, QStringLiteral("namespace:/robot4")));
    QVERIFY(!panel.isNamespaceCollapsed(QStringLiteral("/robot4")));
    QCOMPARE(panel.view()->zoom(), zoom); // not fitted again
    const QGraphicsItem *frame = panel.scene()->item(QStringLiteral("namespace:/robot4"));
    QVERIFY(frame);
    QVERIFY(dynamic_cast<const DiagramClusterItem *>(frame));
    QVERIFY2(shownRect(panel).contains(frame->sceneBoundingRect()),
             "the expanded namespace is in view");
    // robot4's driver, lidar, localizer and planner
    for (const char *part : {"part:part14", "part:part15", "part:part16", "part:part17"}) {
        const QGraphicsItem *box = panel.scene()->item(QString::fromLatin1(part));
        QVERIFY2(box, part);
        QVERIFY2(shownRect(panel).contains(box->sceneBoundingRect()), part);
    }
    saveScreenshot(panel, QStringLiteral("diagram_expanded_in_place.png"));

    // A part: its port rows open where it was, all of it in view.
    const QString planner = QStringLiteral("part:part17");
    QVERIFY(panel.isPartCompact(QStringLiteral("part17")));
    const qreal compactHeight = panel.scene()->item(planner)->sceneBoundingRect().height();
    QVERIFY(expandFromTheCorner(panel, planner));
    QVERIFY(!panel.isPartCompact(QStringLiteral("part17")));
    const QRectF expanded = panel.scene()->item(planner)->sceneBoundingRect();
    QVERIFY(expanded.height() > compactHeight); // its three ports drawn
    QVERIFY2(shownRect(panel).contains(expanded), "the expanded part is in view");
    QCOMPARE(panel.view()->zoom(), zoom);
}

void TestDiagramFirstView::aRootOfIncludesOpensWhereItsNodesAre()
{
    // bringup includes localization (1 node) and navigation, which includes only a
    // navigation_core (3 nodes, one inactive) and an external rviz include: as navigation2's
    // bringup_launch.py includes only other launch files
    using test::diagram::part;
    const auto composite = [](const QString &id, const QString &stem, const QString &parent,
                              QList<RosNodePart> parts) {
        Composite c;
        c.instanceId = id;
        c.stem = stem;
        c.file = QStringLiteral("src/nav/launch/%1.launch.py").arg(stem);
        c.parentId = parent;
        c.parts = std::move(parts);
        return c;
    };
    const auto include = [](const QString &id, const QString &instance, const QString &stem) {
        return part(id, RosNodePart::Kind::Launch, instance, {}, stem, QStringLiteral("/"), {}, 1);
    };
    const auto node = [](const QString &id, const QString &name, bool active = true) {
        RosNodePart p = part(id, RosNodePart::Kind::Node, QStringLiteral("n_") + name, name,
                             QStringLiteral("Server"), QStringLiteral("/"), {}, 2);
        p.active = active;
        return p;
    };
    Architecture arch;
    arch.composites
        << composite(QStringLiteral("lf1"), QStringLiteral("bringup"), {},
                     {include(QStringLiteral("part1"), QStringLiteral("lf2"),
                              QStringLiteral("localization")),
                      include(QStringLiteral("part2"), QStringLiteral("lf3"),
                              QStringLiteral("navigation"))})
        << composite(QStringLiteral("lf2"), QStringLiteral("localization"), QStringLiteral("lf1"),
                     {node(QStringLiteral("part1"), QStringLiteral("amcl"))})
        << composite(QStringLiteral("lf3"), QStringLiteral("navigation"), QStringLiteral("lf1"),
                     {include(QStringLiteral("part1"), QStringLiteral("lf4"),
                              QStringLiteral("navigation_core"))})
        << composite(QStringLiteral("lf4"), QStringLiteral("navigation_core"),
                     QStringLiteral("lf3"),
                     {node(QStringLiteral("part1"), QStringLiteral("planner")),
                      node(QStringLiteral("part2"), QStringLiteral("controller")),
                      node(QStringLiteral("part3"), QStringLiteral("smoother"), false)});
    // down the include that starts the most nodes, to the first that starts one itself
    QCOMPARE(DiagramFirstView::firstComposite(arch, QStringLiteral("lf1"), true),
             QStringLiteral("lf4"));
    QCOMPARE(DiagramFirstView::firstComposite(arch, QStringLiteral("lf2"), true),
             QStringLiteral("lf2")); // a root with a node of its own opens on itself
    {
        // one node of its own beside the include of a system four times its size: the system
        Architecture simulation = arch;
        simulation.composites[0].parts << node(QStringLiteral("part3"), QStringLiteral("rsp"));
        QCOMPARE(DiagramFirstView::firstComposite(simulation, QStringLiteral("lf1"), true),
                 QStringLiteral("lf1")); // 1 of its own, 3 in navigation: itself
        simulation.composites[3].parts << node(QStringLiteral("part4"), QStringLiteral("bt"))
                                       << node(QStringLiteral("part5"), QStringLiteral("behavior"));
        QCOMPARE(DiagramFirstView::firstComposite(simulation, QStringLiteral("lf1"), true),
                 QStringLiteral("lf4"));
    }
    // counted without the inactive node, navigation starts as many as localization: neither
    // is the system, the root shows both
    arch.composites[3].parts.removeAt(1);
    QCOMPARE(DiagramFirstView::firstComposite(arch, QStringLiteral("lf1"), false),
             QStringLiteral("lf1"));
    {
        // one launch file per package, alike in size: the system is all of them
        Architecture packages;
        packages.composites << composite(QStringLiteral("lf1"), QStringLiteral("all"), {}, {});
        for (int r = 1; r <= 3; ++r) {
            const QString id = QStringLiteral("lf%1").arg(r + 1);
            const QString stem = QStringLiteral("pkg_%1").arg(r);
            packages.composites[0].parts << include(QStringLiteral("part%1").arg(r), id, stem);
            packages.composites << composite(
                id, stem, QStringLiteral("lf1"),
                {node(QStringLiteral("part1"), QStringLiteral("drive")),
                 node(QStringLiteral("part2"), QStringLiteral("lidar"))});
        }
        QCOMPARE(DiagramFirstView::firstComposite(packages, QStringLiteral("lf1"), true),
                 QStringLiteral("lf1"));
        // copies of one launch file, one per robot: the first robot's nodes
        for (int r = 1; r <= 3; ++r)
            packages.composites[r].file = QStringLiteral("src/nav/launch/robot.launch.py");
        QCOMPARE(DiagramFirstView::firstComposite(packages, QStringLiteral("lf1"), true),
                 QStringLiteral("lf2"));
    }
    QCOMPARE(DiagramFirstView::firstComposite(arch, QStringLiteral("lf1"), true),
             QStringLiteral("lf4"));
    // nothing under the root starts a node: the root
    Architecture empty;
    empty.composites << composite(QStringLiteral("lf1"), QStringLiteral("bringup"), {}, {});
    QCOMPARE(DiagramFirstView::firstComposite(empty, QStringLiteral("lf1"), true),
             QStringLiteral("lf1"));

    // The panel opens on it, with the way back up on its breadcrumbs.
    DiagramLayouter layouter;
    DiagramPanel panel(&layouter);
    panel.resize(1200, 800);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    arch.composites[3].parts[1].active = true; // planner and smoother
    QVERIFY(laidOut(panel, [&] { panel.setArchitecture(arch); }));
    QCOMPARE(panel.currentComposite(), QStringLiteral("lf4"));
    QCOMPARE(panel.breadcrumbIds(), (QStringList{"lf1", "lf3", "lf4"}));
    QCOMPARE(drawnParts(panel).size(), 2);
}

QTEST_MAIN(TestDiagramFirstView)
#include "tst_diagramfirstview.moc"
