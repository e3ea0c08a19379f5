#include "diagramfirstview.h"
#include "diagramoverview.h"

#include <QHash>

#include <algorithm>

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

} // namespace rosarch
