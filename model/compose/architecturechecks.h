#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"
#include "interfaces/observability.h"

#include <QList>

namespace rosarch {

/// Checks each system started from an entry point (blueprint §1: a root launch file no other
/// file includes under any condition, or the chosen root; with everything it includes, active
/// parts only) for what usually is a mistake: one topic with two types, two servers for one
/// service or action, two nodes with one name, publisher and subscription QoS that cannot
/// match, remaps that match no port (RemapChecks), and open ports (a subscription no one
/// publishes, a publisher no one hears, a client no one serves, a remap to a name nobody
/// uses) where there is evidence of a mistake: a remap another launch file gives the same
/// port and this one lacks, a misspelt name, or a namespace slip (docs/checks.md).
/// Observability outputs are never unheard. Each diagnostic cites the port (or launch line)
/// and, as related locations, the other places that take part.
class ArchitectureChecks
{
public:
    static QList<Diagnostic> run(const Architecture &arch, const AtomicNodeList &nodes,
                                 const LaunchDependencies &launch,
                                 const Observability &observability = Observability::builtIn());
};

} // namespace rosarch
