#include "diagram/diagramoverview.h"

#include <QSet>

namespace rosarch {

DiagramOptions DiagramOverview::options(const Composite &c, DiagramOptions options)
{
    options.collapsedNamespaces.clear();
    QList<const RosNodePart *> parts;
    for (const RosNodePart &part : c.parts)
        if ((options.showInactive || part.active) && (options.showExternal || !part.external))
            parts << &part;
    // Go down while one namespace holds every part: collapsing it would leave a single box.
    for (int depth = 0; depth < 64; ++depth) {
        QSet<QString> level;
        bool beside = false; // a part outside every namespace of this level
        for (const RosNodePart *part : std::as_const(parts)) {
            const QStringList chain = DiagramBuilder::namespaceChain(part->nameSpace);
            if (chain.size() > depth)
                level.insert(chain[depth]);
            else
                beside = true;
        }
        if (level.isEmpty())
            break;
        if (level.size() > 1 || beside) {
            QStringList sorted(level.cbegin(), level.cend());
            sorted.sort();
            options.collapsedNamespaces = sorted;
            break;
        }
    }
    options.collapseBoundary = true;
    options.compactParts.clear();
    for (const RosNodePart *part : std::as_const(parts))
        options.compactParts << part->id;
    return options;
}

double DiagramOverview::boxArea(const LayoutGraph &graph)
{
    double area = 0;
    for (const LayoutNode &n : graph.nodes)
        area += n.width * n.height;
    return area;
}

double DiagramOverview::legibleZoom(double points, double dpi, double pixelSize)
{
    if (pixelSize <= 0 || dpi <= 0)
        return 1.0;
    return points * dpi / 72.0 / pixelSize;
}

} // namespace rosarch
