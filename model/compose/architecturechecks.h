#pragma once

#include "atomicnodelist.h"
#include "composition.h"
#include "launchdependencies.h"
#include "observability.h"

#include <QList>

namespace rosarch {

/// Checks each system started from an entry point (blueprint §1: a root launch file no other
/// file includes under any condition, or the chosen root; with everything it includes, active
/// parts only) for what usually is a mistake: a subscription no one publishes, a publisher no
/// one hears (each with the most similar existing name as a hint; observability outputs are
/// never unheard), one topic with two types, two servers for one service or action, a client
/// no one serves, two nodes with one name, a remap that sends a port to a name nobody uses,
/// publisher and subscription QoS that cannot match, and remaps that match no port. Each
/// diagnostic cites the port (or launch line) and, as related locations, the other places
/// that take part.
class ArchitectureChecks
{
public:
    static QList<Diagnostic> run(const Architecture &arch, const AtomicNodeList &nodes,
                                 const LaunchDependencies &launch,
                                 const Observability &observability = Observability::builtIn());
};

} // namespace rosarch
