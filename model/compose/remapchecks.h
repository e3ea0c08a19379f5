#pragma once

#include "core/atomicnodelist.h"
#include "core/diagnostic.h"
#include "core/launchdependencies.h"

#include <QList>

namespace rosarch {

/// `remap-unmatched`: a remap rule of a judged system (blueprint §1) that renames no port of
/// any node it applies to, reported once at the first node the rule applies to. A port's
/// transport topics count (`~/output/image/compressed`). A rule whose target is empty (an
/// argument nobody sets), or that applies to a node with a port whose name the analysis could
/// not decide, is no judgement on the ports: it is not reported. When the launch file's package
/// is newer than the node's (package.xml versions), the finding says so: the remap may be
/// written for another version of the node.
class RemapChecks
{
public:
    static void run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                    QList<Diagnostic> *out);
};

} // namespace rosarch
