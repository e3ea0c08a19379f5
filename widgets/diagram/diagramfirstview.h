#pragma once

#include "core/composition.h"
#include "diagram/diagrambuilder.h"

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
    /// The composite the first view of system `rootId` opens on, so that it shows the system's
    /// nodes: the root itself when it starts nodes of its own, else, down the include tree, the
    /// included launch file that starts most of the nodes (more than half; of copies of one
    /// launch file, one per robot, the first), until one whose own nodes are at least a
    /// kFewerOwnNodes-th of those its biggest include starts (the breadcrumbs lead back up).
    /// Inactive parts count only with `inactive`. `rootId` when nothing under it starts a node.
    static constexpr int kFewerOwnNodes = 4;
    static QString firstComposite(const Architecture &architecture, const QString &rootId,
                                  bool inactive);
};

} // namespace rosarch
