#pragma once

#include "core/composition.h"

#include <QString>

namespace rosarch {

/// The communication graph of a root system in Graphviz DOT, as rqt_graph draws a running
/// one: every active node started by the root launch file and the files it includes
/// (flattened), every topic, service and action they use by its resolved name, and an edge per
/// port (publisher -> topic -> subscriber, client -> service -> server). Names analysis
/// could not resolve are left out and counted in a comment. Deterministic.
class CommunicationGraph
{
public:
    static QString dot(const Architecture &architecture, const Composite &root);
};

} // namespace rosarch
