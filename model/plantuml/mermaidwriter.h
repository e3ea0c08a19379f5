#pragma once

#include "core/composition.h"

#include <QString>

namespace rosarch {

/// A composite as a Mermaid flowchart inside a markdown file (GitHub renders the fenced
/// block): one subgraph per namespace, parts as boxes (an included launch file as a
/// subroutine box), topics as stadiums, services and actions as hexagons, boundary ports as
/// flags, and arrows coloured like the CCD's (publish green, subscribe blue, client red,
/// server purple). Inactive parts and ports are left out, as in the CCD. Deterministic.
class MermaidWriter
{
public:
    /// The markdown file: a heading naming the launch file, then the ```mermaid block.
    static QString write(const Composite &composite);
    /// Only the flowchart text (what goes inside the fence).
    static QString flowchart(const Composite &composite);
};

} // namespace rosarch
