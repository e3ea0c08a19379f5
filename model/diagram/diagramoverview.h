#pragma once

#include "core/composition.h"
#include "diagram/diagrambuilder.h"
#include "diagram/layoutgraph.h"

namespace rosarch {

/// The overview of a composite too big to read at fit zoom: its outermost namespaces that
/// split it (the shallowest level with more than one, or with parts beside it) collapsed to
/// one box each, every part drawn without its port rows, and the boundary ports of each side
/// as one box; DiagramBuilder then hides the channels inside a box and merges the edges.
class DiagramOverview
{
public:
    /// `options` with the overview's collapsed namespaces and compact parts.
    static DiagramOptions options(const Composite &composite, DiagramOptions options);
    /// The area of a graph's boxes before layout (points²): the layout is at least this big.
    static double boxArea(const LayoutGraph &graph);
    /// The zoom at which text of `pixelSize` shows `points` tall on a screen of `dpi`.
    static double legibleZoom(double points, double dpi, double pixelSize);
};

} // namespace rosarch
