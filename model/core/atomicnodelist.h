#pragma once

#include "core/atomicnode.h"
#include "core/diagnostic.h"
#include "core/rospackage.h"

#include <QList>
#include <QString>

namespace rosarch {

/// Stage 1's result: the List of Atomic ROS Nodes, with the packages and diagnostics.
struct AtomicNodeList
{
    QString workspaceRoot; ///< absolute
    QList<RosPackage> packages;
    QList<AtomicNode> nodes; ///< sorted by package, class name; ids arc_1..arc_n in that order
    QList<Diagnostic> diagnostics;
    bool canceled = false;
    /// Parameters helper code declares on whichever node it is handed (LanguageAnalysis): a
    /// value for one of these names is not judged undeclared.
    QList<ParameterDeclaration> helperParameters = {};

    const AtomicNode *node(const QString &id) const;
    bool operator==(const AtomicNodeList &) const = default;
    QList<const AtomicNode *> nodesOfPackage(const QString &package) const;
};

} // namespace rosarch
