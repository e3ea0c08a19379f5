#include "plantuml/communicationgraph.h"
#include "core/rosnames.h"

#include <QMap>
#include <QSet>

namespace rosarch {

namespace {

QString quoted(const QString &text)
{
    QString out = text;
    out.replace(QLatin1Char('\\'), QStringLiteral("\\\\"));
    out.replace(QLatin1Char('"'), QStringLiteral("\\\""));
    out.replace(QLatin1Char('\n'), QStringLiteral("\\n"));
    return QLatin1Char('"') + out + QLatin1Char('"');
}

struct Graph
{
    QMap<QString, QString> nodes;    ///< fully qualified name -> class
    QMap<QString, QString> channels; ///< "topic /x" -> type
    QSet<QString> edges;             ///< DOT edge lines, sorted on output
    int unresolved = 0;
};

QString colour(PortKind k)
{
    switch (k) {
    case PortKind::Publisher:
        return QStringLiteral("darkgreen");
    case PortKind::Subscriber:
        return QStringLiteral("blue");
    case PortKind::ServiceClient:
    case PortKind::ActionClient:
        return QStringLiteral("red");
    case PortKind::ServiceServer:
    case PortKind::ActionServer:
        break;
    }
    return QStringLiteral("purple");
}

void collect(const Architecture &arch, const Composite &c, Graph *g, int depth)
{
    if (depth > 64) // includes nest far less deeply; a bound all the same
        return;
    for (const RosNodePart &part : c.parts) {
        if (!part.active)
            continue;
        if (part.kind == RosNodePart::Kind::Launch) {
            if (const Composite *child = arch.composite(part.typeId))
                collect(arch, *child, g, depth + 1);
            continue;
        }
        const QString node = RosNames::fullyQualified(part.nameSpace, part.name);
        g->nodes.insert(node, part.typeName);
        for (const PartPort &p : part.ports) {
            if (!p.active)
                continue;
            if (!p.resolved) {
                ++g->unresolved;
                continue;
            }
            // One wiring rule with the CCDs: a name built on a guess meets only names built on
            // a guess ("?" marks it; the label says so).
            const QString channel = portFamilyName(p.kind) + QLatin1Char(' ') + p.name +
                                    (p.guessed ? QStringLiteral("?") : QString());
            if (!g->channels.contains(channel) || g->channels.value(channel).isEmpty())
                g->channels.insert(channel, p.type);
            const QString n = quoted(QStringLiteral("node ") + node);
            const QString t = quoted(channel);
            const QString style = QStringLiteral(" [color=%1]").arg(colour(p.kind));
            // Data flows from the providing side; a client's request goes to the service.
            const bool intoNode = p.kind == PortKind::Subscriber ||
                                  p.kind == PortKind::ServiceServer ||
                                  p.kind == PortKind::ActionServer;
            g->edges.insert(intoNode ? QStringLiteral("  %1 -> %2%3;").arg(t, n, style)
                                     : QStringLiteral("  %1 -> %2%3;").arg(n, t, style));
        }
    }
}

} // namespace

QString CommunicationGraph::dot(const Architecture &architecture, const Composite &root)
{
    Graph g;
    collect(architecture, root, &g, 0);
    QString out = QStringLiteral("digraph %1 {\n").arg(quoted(root.stem));
    out += QStringLiteral("  // communication graph of %1, written by rosarch\n")
               .arg(root.file.isEmpty() ? root.stem : root.file);
    if (g.unresolved > 0)
        out +=
            QStringLiteral("  // %1 ports with unresolved names are not drawn\n").arg(g.unresolved);
    out += QStringLiteral("  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n"
                          "  edge [arrowsize=0.7];\n");
    for (auto it = g.nodes.cbegin(); it != g.nodes.cend(); ++it)
        out += QStringLiteral("  %1 [label=%2, shape=ellipse];\n")
                   .arg(quoted(QStringLiteral("node ") + it.key()),
                        quoted(it.key() + QLatin1Char('\n') + it.value()));
    for (auto it = g.channels.cbegin(); it != g.channels.cend(); ++it) {
        const QString kind = it.key().section(QLatin1Char(' '), 0, 0);
        QString name = it.key().section(QLatin1Char(' '), 1);
        if (name.endsWith(QLatin1Char('?')))
            name = name.chopped(1) + QStringLiteral(" (guessed)");
        const QString shape = kind == QLatin1String("topic")     ? QStringLiteral("box")
                              : kind == QLatin1String("service") ? QStringLiteral("hexagon")
                                                                 : QStringLiteral("octagon");
        out += QStringLiteral("  %1 [label=%2, shape=%3];\n")
                   .arg(quoted(it.key()),
                        quoted(it.value().isEmpty() ? name : name + QLatin1Char('\n') + it.value()),
                        shape);
    }
    QStringList edges(g.edges.begin(), g.edges.end());
    edges.sort();
    for (const QString &e : std::as_const(edges))
        out += e + QLatin1Char('\n');
    return out + QStringLiteral("}\n");
}

} // namespace rosarch
