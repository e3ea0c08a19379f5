#include "core/atomicnodelist.h"

namespace rosarch {

const AtomicNode *AtomicNodeList::node(const QString &id) const
{
    for (const AtomicNode &n : nodes)
        if (n.id == id)
            return &n;
    return nullptr;
}

QList<const AtomicNode *> AtomicNodeList::nodesOfPackage(const QString &package) const
{
    QList<const AtomicNode *> out;
    for (const AtomicNode &n : nodes)
        if (n.packageName == package)
            out.append(&n);
    return out;
}

} // namespace rosarch
