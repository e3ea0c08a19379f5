// The overview of a composite too big to read at fit zoom: which namespaces collapse, which
// parts lose their port rows, the channels hidden inside a box, the edges merged between boxes
// and channels, and that expanding gives back the full diagram.
#include "diagram/diagramoverview.h"
#include "support/diagramarchitecture.h"

#include <QSet>
#include <QtTest>

using namespace rosarch;

namespace {

int edgesAt(const LayoutGraph &g, const QString &nodeId)
{
    int count = 0;
    for (const LayoutEdge &e : g.edges)
        count += (e.tail == nodeId || e.head == nodeId) ? 1 : 0;
    return count;
}

} // namespace

class TestDiagramOverview : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void collapsesRobotNamespacesAndPorts();
    void goesDownToTheNamespacesThatSplit();
    void innerChannelsAndMergedEdges();
    void expandRestores();
    void legibleZoom();
};

void TestDiagramOverview::collapsesRobotNamespacesAndPorts()
{
    const Composite fleet = test::diagram::fleet(4);
    const DiagramOptions o = DiagramOverview::options(fleet, {});
    QCOMPARE(o.collapsedNamespaces, (QStringList{"/robot1", "/robot2", "/robot3", "/robot4"}));
    QCOMPARE(o.compactParts.size(), fleet.parts.size());
    const LayoutGraph g = DiagramBuilder::build(fleet, o);
    // Two parts at the root, one box per robot, no port rows anywhere.
    QStringList nodes;
    for (const LayoutNode &n : g.nodes)
        if (n.key.startsWith(QLatin1String("part:")) ||
            n.key.startsWith(QLatin1String("namespace:"))) {
            nodes << n.label;
            QVERIFY2(n.ports.isEmpty(), qPrintable(n.label));
        }
    QCOMPARE(nodes, (QStringList{"map_server", "/robot1", "/robot2", "/robot3", "/robot4",
                                 "fleet_monitor"}));
    // The boundary: one box per side, the robots' goals in, the fleet's status out.
    QVERIFY(o.collapseBoundary);
    const LayoutNode *in = g.node(DiagramBuilder::collapsedBoundaryKey(true));
    const LayoutNode *out = g.node(DiagramBuilder::collapsedBoundaryKey(false));
    QVERIFY(in && out);
    QCOMPARE(in->label, QStringLiteral("4 ports in"));
    QCOMPARE(out->label, QStringLiteral("1 port out"));
    QCOMPARE(in->rank, LayoutNode::Rank::Source);
    QCOMPARE(edgesAt(g, in->id), 4); // one per robot box
    for (const LayoutNode &n : g.nodes)
        QVERIFY2(n.key == in->key || n.key == out->key ||
                     !n.key.startsWith(QLatin1String("boundary:")),
                 qPrintable(n.key));
    QCOMPARE(g.node(QStringLiteral("part:part1"))->detail, QStringLiteral("MapServer · 2 ports"));
    QCOMPARE(g.node(QStringLiteral("part:part18"))->detail,
             QStringLiteral("FleetMonitor · 6 ports"));
    for (const LayoutEdge &e : g.edges)
        QVERIFY(e.tailPort.isEmpty() && e.headPort.isEmpty());
    QVERIFY(g.clusters.isEmpty());
    // Far smaller than the full diagram.
    const LayoutGraph full = DiagramBuilder::build(fleet);
    QVERIFY(DiagramOverview::boxArea(g) < DiagramOverview::boxArea(full) / 2);
    QVERIFY(g.nodes.size() < full.nodes.size() / 2);
}

void TestDiagramOverview::goesDownToTheNamespacesThatSplit()
{
    // Everything in /site: collapsing /site would leave one box; its children split it.
    Composite c = test::diagram::fleet(2);
    for (RosNodePart &p : c.parts)
        p.nameSpace =
            QStringLiteral("/site") + (p.nameSpace == QLatin1String("/") ? QString() : p.nameSpace);
    const DiagramOptions o = DiagramOverview::options(c, {});
    QCOMPARE(o.collapsedNamespaces, (QStringList{"/site/robot1", "/site/robot2"}));
    // No namespaces at all: nothing collapses, the parts still lose their rows.
    Composite flat = test::diagram::fleet(1);
    for (RosNodePart &p : flat.parts)
        p.nameSpace = QStringLiteral("/");
    const DiagramOptions f = DiagramOverview::options(flat, {});
    QVERIFY(f.collapsedNamespaces.isEmpty());
    QCOMPARE(f.compactParts.size(), flat.parts.size());
    // Hidden parts are not listed.
    DiagramOptions filters;
    filters.showInactive = false;
    const Composite demo = test::diagram::architecture().composites[0];
    QVERIFY(!DiagramOverview::options(demo, filters).compactParts.contains("part3"));
    QVERIFY(DiagramOverview::options(demo, {}).compactParts.contains("part3"));
}

void TestDiagramOverview::innerChannelsAndMergedEdges()
{
    const Composite fleet = test::diagram::fleet(2);
    const LayoutGraph g = DiagramBuilder::build(fleet, DiagramOverview::options(fleet, {}));
    // cmd_vel, odom and scan are only used inside a robot: in its box, not drawn.
    QStringList channels;
    for (const LayoutNode &n : g.nodes)
        if (n.key.startsWith(QLatin1String("channel:")))
            channels << n.label;
    channels.sort();
    QCOMPARE(channels, (QStringList{"/map", "/map_server/reload", "/robot1/pose", "/robot2/pose"}));
    const LayoutNode *robot1 = g.node(QStringLiteral("namespace:/robot1"));
    QVERIFY(robot1);
    QCOMPARE(robot1->detail, QStringLiteral("4 parts, 3 channels, collapsed"));
    // The box's wires, one per channel and kind: publish and subscribe /robot1/pose, subscribe
    // /map, and the goal coming in from the boundary.
    QCOMPARE(edgesAt(g, robot1->id), 4);
    QSet<QString> signatures;
    for (const LayoutEdge &e : g.edges) {
        const QString s = QStringList{e.tail, e.head, QString::number(e.category)}.join('|');
        QVERIFY2(!signatures.contains(s), qPrintable(s));
        signatures.insert(s);
    }
    // The monitor's edges stay one per channel: two poses, the reload client, its status out.
    QCOMPARE(edgesAt(g, QStringLiteral("part:part10")), 4);
}

void TestDiagramOverview::expandRestores()
{
    const Composite fleet = test::diagram::fleet(3);
    DiagramOptions o = DiagramOverview::options(fleet, {});
    // Expanding one robot: its parts come back (still compact), its inner channels too.
    o.collapsedNamespaces.removeAll(QStringLiteral("/robot2"));
    LayoutGraph g = DiagramBuilder::build(fleet, o);
    QVERIFY(!g.node(QStringLiteral("namespace:/robot2")));
    QVERIFY(g.node(QStringLiteral("namespace:/robot1")));
    QVERIFY(g.cluster(QStringLiteral("namespace:/robot2")));
    int robot2Parts = 0;
    for (const LayoutNode &n : g.nodes)
        robot2Parts += n.cluster.startsWith(QLatin1String("namespace:/robot2")) &&
                               n.key.startsWith(QLatin1String("part:"))
                           ? 1
                           : 0;
    QCOMPARE(robot2Parts, 4);
    bool cmdVel = false;
    for (const LayoutNode &n : g.nodes)
        cmdVel |= n.label == QLatin1String("/robot2/cmd_vel");
    QVERIFY(cmdVel);
    // Showing one part's ports again gives back its rows and its port-level edges.
    o.compactParts.removeAll(QStringLiteral("part1"));
    g = DiagramBuilder::build(fleet, o);
    QCOMPARE(g.node(QStringLiteral("part:part1"))->ports.size(), 2);
    QCOMPARE(g.node(QStringLiteral("part:part1"))->detail, QStringLiteral("MapServer"));
    // Expanding everything gives the full diagram, exactly.
    o.collapsedNamespaces.clear();
    o.compactParts.clear();
    QVERIFY(DiagramBuilder::build(fleet, o).node(DiagramBuilder::collapsedBoundaryKey(true)));
    o.collapseBoundary = false;
    QCOMPARE(DiagramBuilder::build(fleet, o), DiagramBuilder::build(fleet));
}

void TestDiagramOverview::legibleZoom()
{
    // 7 pt at 96 dpi is 9.33 px: a 12 px font needs a zoom of at least 0.78.
    QCOMPARE(qRound(DiagramOverview::legibleZoom(7, 96, 12) * 100), 78);
    QCOMPARE(DiagramOverview::legibleZoom(7, 96, 0), 1.0);
}

QTEST_GUILESS_MAIN(TestDiagramOverview)
#include "tst_diagramoverview.moc"
