#include "widgets/diagram/diagramfirstview.h"
#include "diagram/diagramoverview.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <functional>

namespace rosarch {

QList<DiagramOptions> DiagramFirstView::steps(const Composite &c, const DiagramOptions &base)
{
    DiagramOptions full = base;
    full.collapsedNamespaces.clear();
    full.compactParts.clear();
    full.collapseBoundary = false;
    DiagramOptions boundary = full;
    boundary.collapseBoundary = true;
    const DiagramOptions overview = DiagramOverview::options(c, base);
    DiagramOptions compact = boundary;
    compact.compactParts = overview.compactParts;
    compact.compactParts.sort();
    QList<DiagramOptions> out{full, boundary, compact};
    // The namespaces that split the composite are collapsed the biggest first, and of equal
    // ones the last in reading order first: the first namespace stays open longest.
    QHash<QString, int> parts;
    for (const RosNodePart &part : c.parts)
        if (overview.compactParts.contains(part.id))
            for (const QString &ns : DiagramBuilder::namespaceChain(part.nameSpace))
                if (overview.collapsedNamespaces.contains(ns))
                    ++parts[ns];
    QStringList order = overview.collapsedNamespaces;
    std::sort(order.begin(), order.end(), [&parts](const QString &a, const QString &b) {
        return parts.value(a) != parts.value(b) ? parts.value(a) > parts.value(b) : a > b;
    });
    DiagramOptions step = compact;
    for (const QString &ns : std::as_const(order)) {
        step.collapsedNamespaces << ns;
        step.collapsedNamespaces.sort();
        out << step;
    }
    return out;
}

bool DiagramFirstView::sameCollapse(const DiagramOptions &a, const DiagramOptions &b)
{
    QStringList ca = a.compactParts, cb = b.compactParts;
    QStringList na = a.collapsedNamespaces, nb = b.collapsedNamespaces;
    ca.sort();
    cb.sort();
    na.sort();
    nb.sort();
    return a.collapseBoundary == b.collapseBoundary && ca == cb && na == nb;
}

int DiagramFirstView::indexOf(const QList<DiagramOptions> &steps, const DiagramOptions &options)
{
    for (int i = 0; i < steps.size(); ++i)
        if (sameCollapse(steps[i], options))
            return i;
    return -1;
}

QString DiagramFirstView::firstComposite(const Architecture &architecture, const QString &rootId,
                                         bool inactive)
{
    // nodes each composite starts, transitively (an include tree: memo against repeats)
    QHash<QString, int> nodes;
    const std::function<int(const QString &)> count = [&](const QString &id) {
        if (const auto it = nodes.constFind(id); it != nodes.constEnd())
            return *it;
        nodes.insert(id, 0); // a cycle, were there one, counts nothing
        int n = 0;
        if (const Composite *c = architecture.composite(id))
            for (const RosNodePart &p : c->parts)
                if (p.active || inactive)
                    n += p.kind == RosNodePart::Kind::Node ? 1 : count(p.instanceId);
        nodes.insert(id, n);
        return n;
    };
    QString at = rootId;
    QSet<QString> seen;
    while (!seen.contains(at)) {
        seen.insert(at);
        const Composite *c = architecture.composite(at);
        if (!c)
            return rootId;
        QString next;
        int most = 0;
        int own = 0;
        int all = 0;
        QHash<QString, int> byFile; // nodes the includes of each launch file start
        QString nextFile;
        for (const RosNodePart &p : c->parts) {
            if (!p.active && !inactive)
                continue;
            if (p.kind == RosNodePart::Kind::Node) {
                ++own;
                ++all;
                continue;
            }
            const int n = count(p.instanceId);
            const Composite *included = architecture.composite(p.instanceId);
            const QString file = included ? included->file : p.instanceId;
            all += n;
            byFile[file] += n;
            if (n > most) {
                most = n;
                next = p.instanceId;
                nextFile = file;
            }
        }
        // The biggest include goes first when it, with its copies (the same launch file once
        // per robot), starts most of the nodes; includes of many launch files alike in size
        // (one per package) are the system together, shown from here.
        if (!next.isEmpty() && byFile.value(nextFile) * 2 <= all)
            return at;
        // a launch file of its own few nodes around the include of the system (a simulation
        // starting a robot state publisher next to the navigation's bringup) opens on that
        if (own > 0 && own * kFewerOwnNodes >= most)
            return at;
        if (next.isEmpty())
            return own > 0 ? at : rootId;
        at = next;
    }
    return rootId;
}

} // namespace rosarch
