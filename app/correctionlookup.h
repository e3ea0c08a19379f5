#pragma once

// Lookups the correction controller's views and edits share (internal to app/).
#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"

#include <QString>

namespace rosarch::CorrectionLookup {
inline QString channelFamily(Channel::Kind kind)
{
    return kind == Channel::Kind::Topic     ? QStringLiteral("topic")
           : kind == Channel::Kind::Service ? QStringLiteral("service")
                                            : QStringLiteral("action");
}

/// A port of a node list, by "arc_3/p1".
inline const Port *findPort(const AtomicNodeList &nodes, const QString &id)
{
    const AtomicNode *n = nodes.node(id.section(u'/', 0, 0));
    if (!n)
        return nullptr;
    for (const Port &p : n->ports)
        if (p.id == id.section(u'/', 1))
            return &p;
    return nullptr;
}

inline const Channel *findChannel(const Architecture &architecture, const QString &key)
{
    for (const Composite &c : architecture.composites)
        for (const Channel &ch : c.channels)
            if (channelFamily(ch.kind) + u':' + ch.name == key)
                return &ch;
    return nullptr;
}

inline QString portName(const Port &p)
{
    return p.name.isEmpty() ? p.nameExpression : p.name;
}

inline QString instanceName(const NodeInstance &n)
{
    return n.nodeName.isEmpty() ? n.execName : n.nodeName;
}

} // namespace rosarch::CorrectionLookup
