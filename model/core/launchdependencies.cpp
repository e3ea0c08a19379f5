#include "core/launchdependencies.h"

namespace rosarch {

const LaunchFileInstance *LaunchDependencies::instance(const QString &id) const
{
    for (const LaunchFileInstance &i : instances)
        if (i.id == id)
            return &i;
    return nullptr;
}

const NodeInstance *LaunchDependencies::node(const QString &id) const
{
    for (const NodeInstance &n : nodes)
        if (n.id == id)
            return &n;
    return nullptr;
}

} // namespace rosarch
