#pragma once

#include "composition.h"
#include "diagrambuilder.h"

#include <QList>

namespace rosarch {

/// How much of a composite the first view draws in full: the steps from everything drawn to
/// the overview, each smaller than the one before. The first view takes the first step that
/// can be read at the legible zoom, so that a system that fits shows its nodes and only what
/// does not fit is collapsed: the boundary ports first, then the port rows of the parts, then
/// the biggest namespaces one at a time.
class DiagramFirstView
{
public:
    /// The steps for `composite` under the filters of `base`; the last is the overview.
    static QList<DiagramOptions> steps(const Composite &composite, const DiagramOptions &base);
    /// The index of the step `options` draws, or -1 when it is none of them.
    static int indexOf(const QList<DiagramOptions> &steps, const DiagramOptions &options);
    /// True when `a` and `b` collapse the same things.
    static bool sameCollapse(const DiagramOptions &a, const DiagramOptions &b);
};

} // namespace rosarch
