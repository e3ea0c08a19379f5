#include "diagram/diagrambuilder.h"
#include "diagram/graphlayout.h"
#include "support/diagramarchitecture.h"
#include "support/testsupport.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <sys/resource.h>

using namespace rosarch;

namespace {

LayoutNode node(const QString &id, double w, double h, const QString &cluster = {})
{
    LayoutNode n;
    n.id = n.key = id;
    n.label = id;
    n.width = w;
    n.height = h;
    n.cluster = cluster;
    return n;
}

LayoutEdge edge(const QString &id, const QString &tail, const QString &tailPort,
                const QString &head, const QString &headPort = {})
{
    LayoutEdge e;
    e.id = e.key = id;
    e.tail = tail;
    e.tailPort = tailPort;
    e.head = head;
    e.headPort = headPort;
    return e;
}

/// Two nested clusters, a node with ports, a boundary-like source and sink.
LayoutGraph smallGraph()
{
    LayoutGraph g;
    LayoutNode talker = node(QStringLiteral("talker"), 120, 70, QStringLiteral("ns_a"));
    talker.headerHeight = 30;
    talker.rowHeight = 18;
    talker.ports = {{QStringLiteral("s1"), {}, QStringLiteral("in"), true, 0},
                    {QStringLiteral("p1"), {}, QStringLiteral("out"), false, 0},
                    {QStringLiteral("p2"), {}, QStringLiteral("out2"), false, 0}};
    LayoutNode topic = node(QStringLiteral("topic"), 90, 36, QStringLiteral("ns_a"));
    topic.shape = LayoutNode::Shape::Queue;
    LayoutNode service = node(QStringLiteral("service"), 80, 44, QStringLiteral("ns_b"));
    service.shape = LayoutNode::Shape::Ellipse;
    LayoutNode listener = node(QStringLiteral("listener"), 110, 50, QStringLiteral("ns_b"));
    LayoutNode in = node(QStringLiteral("in"), 70, 30);
    in.rank = LayoutNode::Rank::Source;
    LayoutNode out = node(QStringLiteral("out"), 70, 30);
    out.rank = LayoutNode::Rank::Sink;
    g.nodes = {in, talker, topic, service, listener, out};
    g.clusters = {
        {QStringLiteral("ns_a"), {}, QStringLiteral("/a"), {}, 40, 18, 0},
        {QStringLiteral("ns_b"), {}, QStringLiteral("/a/b"), QStringLiteral("ns_a"), 50, 18, 0}};
    g.edges = {
        edge(QStringLiteral("e_in"), QStringLiteral("in"), {}, QStringLiteral("talker"),
             QStringLiteral("s1")),
        edge(QStringLiteral("e_pub"), QStringLiteral("talker"), QStringLiteral("p1"),
             QStringLiteral("topic")),
        edge(QStringLiteral("e_sub"), QStringLiteral("topic"), {}, QStringLiteral("listener")),
        edge(QStringLiteral("e_srv"), QStringLiteral("talker"), QStringLiteral("p2"),
             QStringLiteral("service")),
        edge(QStringLiteral("e_out"), QStringLiteral("listener"), {}, QStringLiteral("out"))};
    return g;
}

} // namespace

class TestGraphLayout : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void realHelperLaysOutTheGraph();
    void dotIsDeterministic();
    void timeoutKillsTheHelper();
    void crashIsReported();
    void environmentChoosesTheHelper();
    void failuresAreMessages();
    void cancelStopsTheHelper();
    void builderKeysEveryElement();
    void builderFiltersAndCollapses();
    void builtDiagramLaysOut();
    void biggerDiagramLaysOut();
    void deepRecursionDoesNotOverflowTheStack();
};

void TestGraphLayout::realHelperLaysOutTheGraph()
{
    QVERIFY2(!GraphLayout::helperPath().isEmpty(), "rosarch-layout not found");
    const LayoutGraph g = smallGraph();
    const LayoutResult r = GraphLayout::layout(g);
    QVERIFY2(r.ok, qPrintable(r.error));
    qInfo("small graph laid out in %lld ms", r.elapsedMs);
    const LayoutGeometry &geo = r.geometry;
    QCOMPARE(geo.nodes.size(), g.nodes.size());
    for (const LayoutNode &n : g.nodes) {
        const QRectF rect = geo.nodes.value(n.id);
        QVERIFY2(std::abs(rect.width() - n.width) < 1.5, qPrintable(n.id));
        QVERIFY2(std::abs(rect.height() - n.height) < 1.5, qPrintable(n.id));
        QVERIFY(geo.bounds.adjusted(-1, -1, 1, 1).contains(rect));
    }
    for (int i = 0; i < g.nodes.size(); ++i)
        for (int j = i + 1; j < g.nodes.size(); ++j)
            QVERIFY2(!geo.nodes[g.nodes[i].id].intersects(geo.nodes[g.nodes[j].id]),
                     qPrintable(g.nodes[i].id + QLatin1Char('/') + g.nodes[j].id));
    for (const LayoutNode &n : g.nodes)
        if (!n.cluster.isEmpty())
            QVERIFY2(geo.clusters.value(n.cluster).contains(geo.nodes.value(n.id)),
                     qPrintable(n.id));
    QVERIFY(geo.clusters.value(QStringLiteral("ns_a"))
                .contains(geo.clusters.value(QStringLiteral("ns_b"))));
    QVERIFY(!geo.nodes.value(QStringLiteral("topic"))
                 .intersects(geo.clusters.value(QStringLiteral("ns_b"))));
    QVERIFY(geo.clusterLabels.value(QStringLiteral("ns_a")).width() >= 40);
    // Left to right, boundary columns outermost.
    for (const LayoutNode &n : g.nodes) {
        QVERIFY(geo.nodes[QStringLiteral("in")].left() <= geo.nodes[n.id].left());
        QVERIFY(geo.nodes[QStringLiteral("out")].right() >= geo.nodes[n.id].right());
    }
    QCOMPARE(geo.edges.size(), g.edges.size());
    for (const LayoutEdge &e : g.edges) {
        const EdgeGeometry &eg = geo.edges[e.id];
        QVERIFY2(eg.points.size() >= 4 && (eg.points.size() - 1) % 3 == 0, qPrintable(e.id));
        QVERIFY2(eg.hasArrowEnd || eg.hasArrowStart, qPrintable(e.id));
    }
    // Edges attach at the ports the drawing puts on the box sides.
    const LayoutNode &talker = g.nodes[1];
    const QRectF t = geo.nodes[talker.id];
    const QPointF p1 = t.topLeft() + talker.portAnchor(QStringLiteral("p1"));
    const QPointF s1 = t.topLeft() + talker.portAnchor(QStringLiteral("s1"));
    const auto touches = [&](const QString &edgeId, const QPointF &port) {
        const EdgeGeometry &eg = geo.edges[edgeId];
        QList<QPointF> ends{eg.points.first(), eg.points.last()};
        if (eg.hasArrowStart)
            ends << eg.arrowStart;
        if (eg.hasArrowEnd)
            ends << eg.arrowEnd;
        for (const QPointF &p : ends)
            if ((p - port).manhattanLength() < 3)
                return true;
        return false;
    };
    QVERIFY(touches(QStringLiteral("e_pub"), p1));
    QVERIFY(touches(QStringLiteral("e_in"), s1));
    QCOMPARE(s1.x(), t.left());
    QCOMPARE(p1.x(), t.right());
}

void TestGraphLayout::dotIsDeterministic()
{
    const QString dot = GraphLayout::toDot(smallGraph());
    QCOMPARE(GraphLayout::toDot(smallGraph()), dot);
    QVERIFY(dot.contains(QLatin1String("rankdir=LR")));
    QVERIFY(dot.contains(QLatin1String("subgraph \"cluster_0\"")));
    QVERIFY(dot.contains(QLatin1String("{ rank=source; \"n0\"; }")));
    QVERIFY(dot.contains(QLatin1String("\"n1\":\"o0\":e -> \"n2\" [id=\"e1\"]")));
    QVERIFY(dot.contains(QLatin1String("PORT=\"i0\"")));
    // The builder too: the same composite gives the same graph and the same DOT.
    const Architecture arch = test::diagram::architecture();
    const LayoutGraph a = DiagramBuilder::build(arch.composites[0]);
    QCOMPARE(DiagramBuilder::build(arch.composites[0]), a);
    QCOMPARE(GraphLayout::toDot(DiagramBuilder::build(arch.composites[0])), GraphLayout::toDot(a));
}

void TestGraphLayout::timeoutKillsTheHelper()
{
    QTemporaryDir dir;
    LayoutOptions options;
    options.helperPath = test::script(dir, QStringLiteral("slow.sh"), "exec sleep 30");
    options.timeoutMs = 300;
    QElapsedTimer clock;
    clock.start();
    const LayoutResult r = GraphLayout::layout(smallGraph(), options);
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("Graphviz did not finish within 0.3 s"));
    QVERIFY(clock.elapsed() < 5000);
    options.timeoutMs = 1000;
    QCOMPARE(GraphLayout::layout(smallGraph(), options).error,
             QStringLiteral("Graphviz did not finish within 1 s"));
}

void TestGraphLayout::crashIsReported()
{
    QTemporaryDir dir;
    LayoutOptions options;
    options.helperPath = test::script(dir, QStringLiteral("abort.sh"), "kill -ABRT $$");
    const LayoutResult r = GraphLayout::layout(smallGraph(), options);
    QVERIFY(!r.ok);
    QCOMPARE(r.error, QStringLiteral("Graphviz crashed (signal 6) on this diagram"));
}

void TestGraphLayout::environmentChoosesTheHelper()
{
    QTemporaryDir dir;
    const QString abort = test::script(dir, QStringLiteral("abort.sh"), "kill -ABRT $$");
    qputenv("ROSARCH_LAYOUT", abort.toLocal8Bit());
    QCOMPARE(GraphLayout::helperPath(), abort);
    const LayoutResult r = GraphLayout::layout(smallGraph());
    qunsetenv("ROSARCH_LAYOUT");
    QVERIFY(r.error.contains(QLatin1String("crashed (signal 6)")));
    QVERIFY(GraphLayout::helperPath().endsWith(QLatin1String("/rosarch-layout")));
}

void TestGraphLayout::failuresAreMessages()
{
    QTemporaryDir dir;
    LayoutOptions options;
    options.helperPath = dir.filePath(QStringLiteral("missing"));
    LayoutResult r = GraphLayout::layout(smallGraph(), options);
    QVERIFY(!r.ok);
    QVERIFY2(r.error.startsWith(QLatin1String("The layout helper ")), qPrintable(r.error));
    QVERIFY(r.error.contains(QLatin1String("could not be started")));

    options.helperPath =
        test::script(dir, QStringLiteral("fail.sh"), "cat >/dev/null; echo boom >&2; exit 3");
    r = GraphLayout::layout(smallGraph(), options);
    QCOMPARE(r.error,
             QStringLiteral("Graphviz could not lay out this diagram (exit code 3). boom"));

    options.helperPath =
        test::script(dir, QStringLiteral("junk.sh"), "cat >/dev/null; echo '{junk'");
    r = GraphLayout::layout(smallGraph(), options);
    QVERIFY(!r.ok);
    QVERIFY(
        r.error.startsWith(QLatin1String("The layout helper wrote output that could not be read")));

    // The real helper rejects text that is not DOT with its own exit code.
    QProcess helper;
    helper.start(GraphLayout::helperPath(), {});
    QVERIFY(helper.waitForStarted());
    helper.write("digraph {");
    helper.closeWriteChannel();
    QVERIFY(helper.waitForFinished());
    QCOMPARE(helper.exitCode(), 2);
}

void TestGraphLayout::cancelStopsTheHelper()
{
    QTemporaryDir dir;
    LayoutOptions options;
    options.helperPath = test::script(dir, QStringLiteral("slow.sh"), "exec sleep 30");
    int polls = 0;
    options.canceled = [&polls] { return ++polls > 2; };
    QElapsedTimer clock;
    clock.start();
    const LayoutResult r = GraphLayout::layout(smallGraph(), options);
    QVERIFY(r.canceled);
    QVERIFY(!r.ok);
    QVERIFY(clock.elapsed() < 5000);
}

void TestGraphLayout::builderKeysEveryElement()
{
    const Architecture arch = test::diagram::architecture();
    const LayoutGraph g = DiagramBuilder::build(arch.composites[0]);
    QStringList keys;
    for (const LayoutNode &n : g.nodes)
        keys << n.key;
    QCOMPARE(keys, QStringList({"boundary:s1", "part:part1", "part:part2", "part:part3",
                                "part:part4", "part:part5", "channel:q_chatter", "channel:c_reset",
                                "channel:a_navigate", "boundary:p1"}));
    QStringList clusters;
    for (const LayoutCluster &c : g.clusters)
        clusters << c.key + QLatin1Char('<') + c.parent;
    QCOMPARE(clusters,
             QStringList({"namespace:/robot1<", "namespace:/robot1/extra<namespace:/robot1"}));
    QCOMPARE(g.edges.size(), arch.composites[0].connections.size());
    const LayoutNode *talker = g.node(QStringLiteral("part:part1"));
    QVERIFY(talker);
    QCOMPARE(talker->label, QStringLiteral("talker"));
    QCOMPARE(talker->detail, QStringLiteral("Talker"));
    QCOMPARE(talker->cluster, QString());
    QCOMPARE(talker->ports.size(), 4);
    QCOMPARE(talker->ports[1].key, QStringLiteral("port:part1/s1"));
    QVERIFY(talker->ports[1].input);
    QVERIFY(talker->ports[1].flags & LayoutParameterDerived);
    QVERIFY(!talker->ports[0].input);
    QVERIFY(g.node(QStringLiteral("part:part2"))->flags & LayoutOpenable);
    QVERIFY(g.node(QStringLiteral("part:part3"))->flags & LayoutInactive);
    QCOMPARE(g.node(QStringLiteral("part:part3"))->cluster,
             QStringLiteral("namespace:/robot1/extra"));
    QVERIFY(!(g.node(QStringLiteral("part:part5"))->flags & LayoutOpenable));
    QCOMPARE(g.node(QStringLiteral("channel:c_reset"))->shape, LayoutNode::Shape::Ellipse);
    QCOMPARE(g.node(QStringLiteral("channel:a_navigate"))->shape, LayoutNode::Shape::Hexagon);
    QCOMPARE(g.node(QStringLiteral("boundary:s1"))->rank, LayoutNode::Rank::Source);
    QCOMPARE(g.node(QStringLiteral("boundary:p1"))->rank, LayoutNode::Rank::Sink);
    QVERIFY(!(g.node(QStringLiteral("boundary:s1"))->flags & LayoutUnresolved));
    // Publish leaves the part's port; subscribe and server arrive at a port; delegations dash.
    QCOMPARE(g.edges[0].tail, QStringLiteral("part:part1"));
    QCOMPARE(g.edges[0].tailPort, QStringLiteral("p1"));
    QCOMPARE(g.edges[0].head, QStringLiteral("channel:q_chatter"));
    QCOMPARE(g.edges[3].tail, QStringLiteral("channel:c_reset"));
    QCOMPARE(g.edges[3].head, QStringLiteral("part:part2"));
    QCOMPARE(g.edges[3].headPort, QStringLiteral("ps1"));
    QVERIFY(g.edges[6].dashed && !g.edges[0].dashed);
    QCOMPARE(g.edges[6].key, QStringLiteral("connection:6"));
    // The child: an unresolved port name keeps its guess with a "?".
    const LayoutGraph child = DiagramBuilder::build(arch.composites[1]);
    QCOMPARE(child.node(QStringLiteral("part:part1"))->ports[2].label,
             QStringLiteral("?topic_name"));
    QVERIFY(child.node(QStringLiteral("part:part1"))->ports[2].flags & LayoutUnresolved);
    // A boundary port whose name rests on a guessed launch value is drawn as unresolved too.
    Composite guessed = arch.composites[0];
    for (BoundaryPort &b : guessed.boundary)
        b.guessed = b.id == QLatin1String("s1");
    const LayoutGraph marked = DiagramBuilder::build(guessed);
    QVERIFY(marked.node(QStringLiteral("boundary:s1"))->flags & LayoutUnresolved);
    QVERIFY(!(marked.node(QStringLiteral("boundary:p1"))->flags & LayoutUnresolved));
    // Names come from files: a newline or an escape in one is drawn as an escape, on one line.
    Composite hostile = arch.composites[0];
    hostile.parts[0].name = QStringLiteral("new\nline");
    hostile.parts[0].ports[0].nameAsWritten = QStringLiteral("red\x1b[31m");
    hostile.boundary[0].name = QStringLiteral("/a\tb\x07");
    const LayoutGraph escaped = DiagramBuilder::build(hostile);
    const LayoutNode *part = escaped.node(QStringLiteral("part:") + hostile.parts[0].id);
    QVERIFY(part);
    QCOMPARE(part->label, QStringLiteral("new\\x0aline"));
    QVERIFY2(part->ports[0].label.endsWith(QStringLiteral("red\\x1b[31m")),
             qPrintable(part->ports[0].label));
    QCOMPARE(escaped.node(QStringLiteral("boundary:") + hostile.boundary[0].id)->label,
             QStringLiteral("/a\\x09b\\x07"));

    const DiagramKey port = DiagramKey::parse(QStringLiteral("port:part1/s1"));
    QCOMPARE(port.kind, DiagramKey::Kind::Port);
    QCOMPARE(port.id, QStringLiteral("part1"));
    QCOMPARE(port.portId, QStringLiteral("s1"));
    QCOMPARE(DiagramKey::parse(QStringLiteral("namespace:/a/b")).id, QStringLiteral("/a/b"));
    QCOMPARE(DiagramKey::parse(QStringLiteral("connection:6")).index(), 6);
}

void TestGraphLayout::builderFiltersAndCollapses()
{
    const Composite root = test::diagram::architecture().composites[0];
    DiagramOptions o;
    o.showParameterPorts = false;
    LayoutGraph g = DiagramBuilder::build(root, o);
    QCOMPARE(g.node(QStringLiteral("part:part1"))->ports.size(), 3);
    QVERIFY(!g.node(QStringLiteral("boundary:s1"))); // its only delegation is gone
    QCOMPARE(g.edges.size(), 7);

    o = {};
    o.showInactive = false;
    g = DiagramBuilder::build(root, o);
    QVERIFY(!g.node(QStringLiteral("part:part3")));
    QVERIFY(!g.node(QStringLiteral("boundary:p1")));
    QVERIFY(!g.cluster(QStringLiteral("namespace:/robot1/extra")));

    o = {};
    o.showExternal = false;
    g = DiagramBuilder::build(root, o);
    QVERIFY(!g.node(QStringLiteral("part:part5")));
    QVERIFY(g.node(QStringLiteral("part:part2")));

    o = {};
    o.collapsedNamespaces = {QStringLiteral("/robot1")};
    g = DiagramBuilder::build(root, o);
    QVERIFY(!g.node(QStringLiteral("part:part2")));
    QVERIFY(!g.node(QStringLiteral("part:part3")));
    QVERIFY(!g.node(QStringLiteral("part:part4")));
    QVERIFY(g.clusters.isEmpty());
    const LayoutNode *box = g.node(QStringLiteral("namespace:/robot1"));
    QVERIFY(box);
    QCOMPARE(box->shape, LayoutNode::Shape::Folder);
    QCOMPARE(box->detail, QStringLiteral("3 parts, collapsed"));
    int toBox = 0;
    for (const LayoutEdge &e : g.edges)
        if (e.head == box->id || e.tail == box->id) {
            ++toBox;
            QVERIFY(e.headPort.isEmpty() && e.tailPort.isEmpty());
        }
    QCOMPARE(toBox, 4); // subscribe, server, action server, delegation out
}

void TestGraphLayout::builtDiagramLaysOut()
{
    const Architecture arch = test::diagram::architecture();
    for (const Composite &c : arch.composites) {
        const LayoutGraph g = DiagramBuilder::build(c);
        const LayoutResult r = GraphLayout::layout(g);
        QVERIFY2(r.ok, qPrintable(r.error));
        qInfo("composite %s: %lld nodes, %lld edges laid out in %lld ms", qPrintable(c.stem),
              qint64(g.nodes.size()), qint64(g.edges.size()), r.elapsedMs);
        QCOMPARE(r.geometry.nodes.size(), g.nodes.size());
        QCOMPARE(r.geometry.edges.size(), g.edges.size());
        for (const LayoutCluster &cl : g.clusters)
            QVERIFY(r.geometry.clusters.contains(cl.id));
    }
}

void TestGraphLayout::biggerDiagramLaysOut()
{
    const Composite fleet = test::diagram::fleet(4);
    QCOMPARE(fleet.parts.size(), 18);
    const LayoutGraph g = DiagramBuilder::build(fleet);
    const LayoutResult r = GraphLayout::layout(g);
    QVERIFY2(r.ok, qPrintable(r.error));
    qInfo("fleet(4): %lld nodes, %lld clusters, %lld edges laid out in %lld ms",
          qint64(g.nodes.size()), qint64(g.clusters.size()), qint64(g.edges.size()), r.elapsedMs);
    for (int i = 0; i < g.nodes.size(); ++i)
        for (int j = i + 1; j < g.nodes.size(); ++j)
            QVERIFY(!r.geometry.nodes[g.nodes[i].id].intersects(r.geometry.nodes[g.nodes[j].id]));
    // A topic between two parts of one namespace is drawn inside that namespace.
    const LayoutNode *odom = g.node(QStringLiteral("channel:q_robot1_odom"));
    QVERIFY(odom);
    QCOMPARE(odom->cluster, QStringLiteral("namespace:/robot1"));
    QVERIFY(r.geometry.clusters[odom->cluster].contains(r.geometry.nodes[odom->id]));
    QCOMPARE(g.node(QStringLiteral("channel:q_map"))->cluster, QString());
    for (const LayoutCluster &c : g.clusters)
        for (const LayoutNode &n : g.nodes)
            if (n.cluster == c.id)
                QVERIFY(r.geometry.clusters[c.id].contains(r.geometry.nodes[n.id]));
}

void TestGraphLayout::deepRecursionDoesNotOverflowTheStack()
{
    // Graphviz's network simplex recurses once per node of a spanning tree: a chain of 3,000
    // boxes overflows a 256 KB stack (as 600 launch-file boxes in one rank overflowed the
    // default 8 MB one). The helper lays out on a thread of its own, with a big stack.
    LayoutGraph chain;
    for (int i = 0; i < 3000; ++i) {
        chain.nodes << node(QStringLiteral("n%1").arg(i), 72, 36);
        if (i > 0)
            chain.edges << edge(QStringLiteral("e%1").arg(i), QStringLiteral("n%1").arg(i - 1), {},
                                QStringLiteral("n%1").arg(i));
    }
    QProcess helper;
    helper.setChildProcessModifier([] {
        const rlimit small{256 * 1024, 256 * 1024};
        setrlimit(RLIMIT_STACK, &small);
    });
    helper.start(GraphLayout::helperPath(), {});
    QVERIFY(helper.waitForStarted());
    helper.write(GraphLayout::toDot(chain).toUtf8());
    helper.closeWriteChannel();
    QVERIFY(helper.waitForFinished(120000));
    QCOMPARE(helper.exitStatus(), QProcess::NormalExit);
    QCOMPARE(helper.exitCode(), 0);
    LayoutGeometry geometry;
    QString error;
    QVERIFY2(GraphLayout::parseGeometry(helper.readAllStandardOutput(), chain, &geometry, &error),
             qPrintable(error));
    QCOMPARE(geometry.nodes.size(), chain.nodes.size());
    // left to right, one rank after the other
    QVERIFY(geometry.nodes[QStringLiteral("n0")].right() <
            geometry.nodes[QStringLiteral("n1")].left());
}

QTEST_GUILESS_MAIN(TestGraphLayout)
#include "tst_graphlayout.moc"
