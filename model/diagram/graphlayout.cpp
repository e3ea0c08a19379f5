#include "diagram/graphlayout.h"
#include "core/helperprogram.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>

#include <algorithm>
#include <cmath>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::GraphLayout", text);
}

QString num(double v)
{
    return QString::number(v, 'f', 4);
}

int points(double v)
{
    return std::max(0, int(std::lround(v)));
}

/// A comment naming the graph's own id next to the DOT name, for reading the DOT by hand.
QString comment(const QString &id)
{
    QString safe = id;
    for (QChar &c : safe)
        if (!c.isLetterOrNumber() && !QStringLiteral("_/:.-").contains(c))
            c = QLatin1Char('_');
    return QStringLiteral(" // ") + safe;
}

/// An HTML-like table of fixed-size empty cells: it gives the node (or cluster label) an exact
/// size and a named cell per port row, so edges attach where the drawing puts the ports.
QString tableLabel(const LayoutNode &n)
{
    const int width = points(n.width);
    const int left = width / 2;
    const int right = width - left;
    const int header = points(n.headerHeight);
    const int row = points(n.rowHeight);
    const int rows = n.rowCount();
    const int footer = std::max(0, points(n.height) - header - rows * row);
    const auto cell = [](const QString &port, int w, int h, int span = 1) {
        return QStringLiteral("<TD%1%2 FIXEDSIZE=\"TRUE\" WIDTH=\"%3\" HEIGHT=\"%4\"></TD>")
            .arg(port.isEmpty() ? QString() : QStringLiteral(" PORT=\"%1\"").arg(port),
                 span > 1 ? QStringLiteral(" COLSPAN=\"%1\"").arg(span) : QString())
            .arg(w)
            .arg(h);
    };
    QStringList inputs;
    QStringList outputs;
    for (int i = 0, in = 0, out = 0; i < n.ports.size(); ++i)
        (n.ports[i].input ? inputs : outputs)
            << QStringLiteral("%1%2")
                   .arg(n.ports[i].input ? QLatin1Char('i') : QLatin1Char('o'))
                   .arg(n.ports[i].input ? in++ : out++);
    QString t = QStringLiteral("<<TABLE BORDER=\"0\" CELLBORDER=\"0\" CELLSPACING=\"0\" "
                               "CELLPADDING=\"0\">");
    if (header > 0)
        t += QStringLiteral("<TR>") + cell({}, width, header, 2) + QStringLiteral("</TR>");
    for (int r = 0; r < rows; ++r)
        t += QStringLiteral("<TR>") + cell(inputs.value(r), left, row) +
             cell(outputs.value(r), right, row) + QStringLiteral("</TR>");
    if (footer > 0)
        t += QStringLiteral("<TR>") + cell({}, width, footer, 2) + QStringLiteral("</TR>");
    return t + QStringLiteral("</TABLE>>");
}

QString nodeStatement(const LayoutNode &n, int index)
{
    QString attributes;
    if (!n.ports.isEmpty()) {
        attributes = QStringLiteral("shape=none, width=0, height=0, fixedsize=false, label=%1")
                         .arg(tableLabel(n));
    } else {
        QString shape = QStringLiteral("box");
        if (n.shape == LayoutNode::Shape::Ellipse)
            shape = QStringLiteral("ellipse");
        else if (n.shape == LayoutNode::Shape::Hexagon)
            shape = QStringLiteral("hexagon");
        attributes = QStringLiteral("shape=%1, width=%2, height=%3")
                         .arg(shape, num(points(n.width) / 72.0), num(points(n.height) / 72.0));
    }
    return QStringLiteral("\"n%1\" [%2];%3\n").arg(index).arg(attributes, comment(n.id));
}

QString portReference(const LayoutNode &n, const QString &portId)
{
    if (portId.isEmpty())
        return {};
    for (const LayoutPort &p : n.ports)
        if (p.id == portId)
            return QStringLiteral(":\"%1%2\":%3")
                .arg(p.input ? QLatin1Char('i') : QLatin1Char('o'))
                .arg(n.sideIndex(portId))
                .arg(p.input ? QStringLiteral("w") : QStringLiteral("e"));
    return {};
}

void writeCluster(QString &out, const LayoutGraph &graph, int clusterIndex, int depth)
{
    const QString indent(depth * 2, QLatin1Char(' '));
    const LayoutCluster &c = graph.clusters[clusterIndex];
    out += QStringLiteral("%1subgraph \"cluster_%2\" {%3\n")
               .arg(indent)
               .arg(clusterIndex)
               .arg(comment(c.id));
    out += QStringLiteral("%1  label=<<TABLE BORDER=\"0\" CELLBORDER=\"0\" CELLSPACING=\"0\" "
                          "CELLPADDING=\"0\"><TR><TD FIXEDSIZE=\"TRUE\" WIDTH=\"%2\" "
                          "HEIGHT=\"%3\"></TD></TR></TABLE>>;\n")
               .arg(indent)
               .arg(points(c.labelWidth))
               .arg(points(c.labelHeight));
    out += QStringLiteral("%1  labeljust=l; labelloc=t; margin=10;\n").arg(indent);
    for (int i = 0; i < graph.nodes.size(); ++i)
        if (graph.nodes[i].cluster == c.id)
            out += indent + QStringLiteral("  ") + nodeStatement(graph.nodes[i], i);
    for (int i = 0; i < graph.clusters.size(); ++i)
        if (graph.clusters[i].parent == c.id)
            writeCluster(out, graph, i, depth + 1);
    out += indent + QStringLiteral("}\n");
}

QPointF point(const QJsonValue &v, const QPointF &origin)
{
    const QJsonArray a = v.toArray();
    return {a.at(0).toDouble() - origin.x(), origin.y() - a.at(1).toDouble()};
}

QString seconds(int ms)
{
    return ms % 1000 == 0 ? QString::number(ms / 1000) : QString::number(ms / 1000.0, 'f', 1);
}

} // namespace

QString GraphLayout::toDot(const LayoutGraph &graph)
{
    QHash<QString, int> nodeIndex;
    for (int i = 0; i < graph.nodes.size(); ++i)
        nodeIndex.insert(graph.nodes[i].id, i);

    QString out = QStringLiteral("digraph rosarch {\n");
    out += QStringLiteral("  graph [rankdir=LR, splines=true, nodesep=%1, ranksep=%2, "
                          "fontname=\"Helvetica\", fontsize=10];\n")
               .arg(num(graph.nodeSeparation / 72.0), num(graph.rankSeparation / 72.0));
    out += QStringLiteral("  node [label=\"\", margin=0, fixedsize=true];\n");
    out += QStringLiteral("  edge [arrowsize=0.8];\n");
    for (int i = 0; i < graph.nodes.size(); ++i)
        if (graph.nodes[i].cluster.isEmpty() || !graph.cluster(graph.nodes[i].cluster))
            out += QStringLiteral("  ") + nodeStatement(graph.nodes[i], i);
    for (int i = 0; i < graph.clusters.size(); ++i)
        if (graph.clusters[i].parent.isEmpty() || !graph.cluster(graph.clusters[i].parent))
            writeCluster(out, graph, i, 1);
    for (const auto rank : {LayoutNode::Rank::Source, LayoutNode::Rank::Sink}) {
        QStringList members;
        for (int i = 0; i < graph.nodes.size(); ++i)
            if (graph.nodes[i].rank == rank)
                members << QStringLiteral("\"n%1\";").arg(i);
        if (!members.isEmpty())
            out += QStringLiteral("  { rank=%1; %2 }\n")
                       .arg(rank == LayoutNode::Rank::Source ? QStringLiteral("source")
                                                             : QStringLiteral("sink"),
                            members.join(QLatin1Char(' ')));
    }
    for (int i = 0; i < graph.edges.size(); ++i) {
        const LayoutEdge &e = graph.edges[i];
        const int tail = nodeIndex.value(e.tail, -1);
        const int head = nodeIndex.value(e.head, -1);
        if (tail < 0 || head < 0)
            continue;
        out += QStringLiteral("  \"n%1\"%2 -> \"n%3\"%4 [id=\"e%5\"%6];%7\n")
                   .arg(tail)
                   .arg(portReference(graph.nodes[tail], e.tailPort))
                   .arg(head)
                   .arg(portReference(graph.nodes[head], e.headPort))
                   .arg(i)
                   .arg(e.dashed ? QStringLiteral(", style=dashed") : QString(), comment(e.id));
    }
    out += QStringLiteral("}\n");
    return out;
}

QString GraphLayout::helperPath(const LayoutOptions &options)
{
    return findHelperProgram(options.helperPath, "ROSARCH_LAYOUT",
                             QStringLiteral("rosarch-layout"));
}

LayoutResult GraphLayout::layout(const LayoutGraph &graph, const LayoutOptions &options)
{
    LayoutResult result;
    QElapsedTimer clock;
    clock.start();
    const QString helper = helperPath(options);
    if (helper.isEmpty()) {
        result.error = tr("The layout helper rosarch-layout was not found next to the "
                          "application. Set ROSARCH_LAYOUT to its path.");
        return result;
    }
    QProcess process;
    process.setProgram(helper);
    process.start();
    if (!process.waitForStarted(10000)) {
        result.error = tr("The layout helper %1 could not be started: %2")
                           .arg(QDir::toNativeSeparators(helper), process.errorString());
        return result;
    }
    process.write(toDot(graph).toUtf8());
    process.closeWriteChannel();
    while (process.state() != QProcess::NotRunning) {
        if (process.waitForFinished(50))
            break;
        const bool canceled = options.canceled && options.canceled();
        if (canceled || clock.elapsed() > options.timeoutMs) {
            process.kill();
            process.waitForFinished(5000);
            result.canceled = canceled;
            result.error =
                canceled
                    ? tr("The layout was canceled.")
                    : tr("Graphviz did not finish within %1 s").arg(seconds(options.timeoutMs));
            result.elapsedMs = clock.elapsed();
            return result;
        }
    }
    result.elapsedMs = clock.elapsed();
    if (process.exitStatus() == QProcess::CrashExit) {
        result.error = tr("Graphviz crashed (signal %1) on this diagram").arg(process.exitCode());
        return result;
    }
    if (process.exitCode() != 0) {
        const QString detail = QString::fromUtf8(process.readAllStandardError()).trimmed();
        result.error = tr("Graphviz could not lay out this diagram (exit code %1). %2")
                           .arg(process.exitCode())
                           .arg(detail)
                           .trimmed();
        return result;
    }
    result.ok =
        parseGeometry(process.readAllStandardOutput(), graph, &result.geometry, &result.error);
    return result;
}

bool GraphLayout::parseGeometry(const QByteArray &json, const LayoutGraph &graph,
                                LayoutGeometry *geometry, QString *error)
{
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &parseError);
    if (!doc.isObject()) {
        *error = tr("The layout helper wrote output that could not be read: %1")
                     .arg(parseError.errorString());
        return false;
    }
    const QJsonObject root = doc.object();
    const QJsonArray bb = root.value(QLatin1String("bb")).toArray();
    // Graphviz's y axis points up; the scene's points down.
    const QPointF origin(bb.at(0).toDouble(), bb.at(3).toDouble());
    geometry->bounds = QRectF(0, 0, bb.at(2).toDouble() - bb.at(0).toDouble(),
                              bb.at(3).toDouble() - bb.at(1).toDouble());
    const auto indexOf = [](const QString &name, QLatin1String prefix) {
        bool ok = name.startsWith(prefix);
        const int index = ok ? name.mid(prefix.size()).toInt(&ok) : -1;
        return ok ? index : -1;
    };
    for (const QJsonValue &v : root.value(QLatin1String("nodes")).toArray()) {
        const QJsonObject n = v.toObject();
        const int index = indexOf(n.value(QLatin1String("name")).toString(), QLatin1String("n"));
        if (index < 0 || index >= graph.nodes.size())
            continue;
        const QPointF c =
            point(QJsonArray{n.value(QLatin1String("x")), n.value(QLatin1String("y"))}, origin);
        const double w = n.value(QLatin1String("width")).toDouble();
        const double h = n.value(QLatin1String("height")).toDouble();
        geometry->nodes.insert(graph.nodes[index].id, QRectF(c.x() - w / 2, c.y() - h / 2, w, h));
    }
    for (const QJsonValue &v : root.value(QLatin1String("clusters")).toArray()) {
        const QJsonObject c = v.toObject();
        const int index =
            indexOf(c.value(QLatin1String("name")).toString(), QLatin1String("cluster_"));
        if (index < 0 || index >= graph.clusters.size())
            continue;
        const QJsonArray b = c.value(QLatin1String("bb")).toArray();
        const QPointF topLeft = point(QJsonArray{b.at(0), b.at(3)}, origin);
        const QPointF bottomRight = point(QJsonArray{b.at(2), b.at(1)}, origin);
        const QString id = graph.clusters[index].id;
        geometry->clusters.insert(id, QRectF(topLeft, bottomRight));
        const QJsonArray l = c.value(QLatin1String("label")).toArray();
        if (l.size() == 4) {
            const QPointF center = point(QJsonArray{l.at(0), l.at(1)}, origin);
            const QSizeF size(l.at(2).toDouble(), l.at(3).toDouble());
            geometry->clusterLabels.insert(
                id, QRectF(center - QPointF(size.width() / 2, size.height() / 2), size));
        }
    }
    for (const QJsonValue &v : root.value(QLatin1String("edges")).toArray()) {
        const QJsonObject e = v.toObject();
        const int index = indexOf(e.value(QLatin1String("id")).toString(), QLatin1String("e"));
        if (index < 0 || index >= graph.edges.size())
            continue;
        EdgeGeometry g;
        for (const QJsonValue &s : e.value(QLatin1String("splines")).toArray()) {
            const QJsonObject spline = s.toObject();
            for (const QJsonValue &p : spline.value(QLatin1String("points")).toArray())
                g.points << point(p, origin);
            if (spline.contains(QLatin1String("start")) && !g.hasArrowStart) {
                g.hasArrowStart = true;
                g.arrowStart = point(spline.value(QLatin1String("start")), origin);
            }
            if (spline.contains(QLatin1String("end"))) {
                g.hasArrowEnd = true;
                g.arrowEnd = point(spline.value(QLatin1String("end")), origin);
            }
        }
        geometry->edges.insert(graph.edges[index].id, g);
    }
    if (geometry->nodes.size() != graph.nodes.size()) {
        *error = tr("The layout helper left %1 of %2 elements without a position.")
                     .arg(graph.nodes.size() - geometry->nodes.size())
                     .arg(graph.nodes.size());
        return false;
    }
    return true;
}

} // namespace rosarch
