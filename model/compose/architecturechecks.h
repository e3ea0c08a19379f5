#pragma once

#include "atomicnodelist.h"
#include "composition.h"
#include "launchdependencies.h"

#include <QList>

namespace rosarch {

/// Checks each root system (a root launch file with everything it includes, active parts
/// only) for what usually is a mistake: a subscription no one publishes, a publisher no one
/// hears, one topic with two types, two servers for one service or action, a client no one
/// serves, and remaps that match no port. Each diagnostic cites the port (or launch line).
class ArchitectureChecks
{
public:
    static QList<Diagnostic> run(const Architecture &arch, const AtomicNodeList &nodes,
                                 const LaunchDependencies &launch);
};

} // namespace rosarch
