#include "diagram/layoutgraph.h"

#include <algorithm>

namespace rosarch {

int LayoutNode::sideIndex(const QString &portId) const
{
    int inputs = 0;
    int outputs = 0;
    for (const LayoutPort &p : ports) {
        if (p.id == portId)
            return p.input ? inputs : outputs;
        (p.input ? inputs : outputs)++;
    }
    return -1;
}

QPointF LayoutNode::portAnchor(const QString &portId) const
{
    const int index = sideIndex(portId);
    if (index < 0)
        return {width / 2, height / 2};
    bool input = true;
    for (const LayoutPort &p : ports)
        if (p.id == portId)
            input = p.input;
    return {input ? 0.0 : width, headerHeight + (index + 0.5) * rowHeight};
}

int LayoutNode::rowCount() const
{
    int inputs = 0;
    for (const LayoutPort &p : ports)
        inputs += p.input ? 1 : 0;
    return std::max(inputs, int(ports.size()) - inputs);
}

const LayoutNode *LayoutGraph::node(const QString &id) const
{
    for (const LayoutNode &n : nodes)
        if (n.id == id)
            return &n;
    return nullptr;
}

const LayoutCluster *LayoutGraph::cluster(const QString &id) const
{
    for (const LayoutCluster &c : clusters)
        if (c.id == id)
            return &c;
    return nullptr;
}

} // namespace rosarch
