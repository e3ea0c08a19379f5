#pragma once

#include "core/atomicnodelist.h"
#include "core/rospackage.h"

#include <QHash>
#include <QList>
#include <QString>

#include <utility>

namespace rosarch {

/// Which classes of stage 1 a launch action starts: by package and executable, by component
/// plugin, by an executable another package builds, and by qualified name (child nodes).
class NodeClasses
{
public:
    /// Refers to `nodes`, which must outlive it.
    explicit NodeClasses(const AtomicNodeList &nodes);

    /// The classes an executable starts (several when its main spins more than one node), or
    /// the class of a component plugin.
    QList<const AtomicNode *> started(const QString &package, const QString &executable,
                                      bool plugin) const;
    /// One node a process runs: its class, and the construction in the executable's own code
    /// that makes it (null when the class is simply the executable's node).
    using Start = std::pair<const AtomicNode *, const NodeConstruction *>;
    /// The nodes a process of `executable`, whose classes are `classes`, runs: one per class, or,
    /// for an executable that builds its nodes in its own code, one per construction there
    /// (blueprint §1, "Nodes built in code").
    static QList<Start> starts(const QList<const AtomicNode *> &classes, const QString &executable);
    /// The classes of `executable` when exactly one workspace package builds it (a launch file
    /// may name it under another package, which it is installed into); `builtBy` names it.
    QList<const AtomicNode *> elsewhere(const QString &executable, QString *builtBy) const;
    /// The node class (not a plugin, not a procedural node) of this qualified name, or null.
    const AtomicNode *node(const QString &qualifiedName) const;

    /// Whether `package`'s build files declare an executable `name`.
    static bool declares(const RosPackage *package, const QString &name);

private:
    QHash<QString, QList<const AtomicNode *>> m_byExecutable; ///< package \0 executable
    QHash<QString, QList<const AtomicNode *>> m_byExecutableName;
    QHash<QString, const AtomicNode *> m_byPlugin;
    QHash<QString, const AtomicNode *> m_byQualifiedName;
};

} // namespace rosarch
