#pragma once

#include "diagram/graphlayout.h"
#include "diagram/layoutgraph.h"

namespace rosarch {

/// Graphviz `dot` layout in this process (libgvc), for the architecture site: the same DOT
/// (GraphLayout::toDot) and the same coordinates as the GUI's helper process gives, without
/// a process per diagram. Calls are serialized (libgvc keeps global state) and run on a
/// thread with a big stack (dot's network simplex recurses once per node of its auxiliary
/// graph). Graphviz has no time limit here: the site lays out only diagrams the overview
/// keeps small.
class InProcessLayout
{
public:
    static LayoutResult layout(const LayoutGraph &graph);
    /// The Graphviz version linked in ("2.42.2").
    static QString graphvizVersion();
};

} // namespace rosarch
