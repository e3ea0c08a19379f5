#pragma once

#include "core/diagnostic.h"
#include "core/port.h"
#include "nodes/python/pythondefinitionindex.h"
#include "nodes/python/pythonmodulefacts.h"

#include <QList>
#include <QString>

#include <functional>

namespace rosarch {

/// py_trees' setup protocol: `tree.setup(node=self)` hands the node to every behaviour of the
/// tree, so the ports the behaviours create in `setup` belong to the node. The tree is made of
/// the workspace classes built where the node sets it up. Also keeps the bounds on following
/// helpers and the diagnostics for where they were hit.
class PythonSetupProtocol
{
public:
    /// Levels of helpers, base classes and calls followed from a node.
    static constexpr int kMaxDepth = 8;
    /// Classes followed for one setup call: a tree of a few dozen behaviours is usual.
    static constexpr int kMaxInstantiations = 256;
    /// Classes and functions entered for one setup call.
    static constexpr int kMaxVisits = 2000;

    using NodeTest = std::function<bool(int classId)>;
    using HelperPorts = std::function<QList<Port>(const PythonHandoff &handoff,
                                                  const PythonScopeFacts &from, int depth)>;

    /// `isNode` tells node classes (never behaviours); `helperPorts` follows a handoff of the
    /// node made in a behaviour's setup.
    PythonSetupProtocol(const PythonDefinitionIndex &index, NodeTest isNode,
                        HelperPorts helperPorts);

    /// `tree.setup(node=self)`, `root.setup(node=node)`, `behaviour.setup(self)`.
    static bool isSetupHandoff(const PythonHandoff &handoff);
    /// Ports of the objects built in `from` that receive the node through `setup(node=...)`.
    QList<Port> setupPorts(const PythonHandoff &handoff, const PythonScopeFacts &from,
                           int depth) const;
    /// Notes (once) that following `what` stopped at `at` because a bound was hit.
    void reportBound(const Evidence &at, const QString &what) const;
    /// The bounds hit so far, in the order they were hit.
    const QList<Diagnostic> &diagnostics() const { return m_diagnostics; }

private:
    struct MethodPort
    {
        Port port;
        QString method;
    };
    /// A workspace class built while a node's tree (or helper) is made, and how it is reached.
    struct Instantiation
    {
        int id = -1;
        QList<PythonArgument> arguments;
        QList<Evidence> chain; ///< call sites from the node's scope to the instantiation
    };
    struct Reach
    {
        QList<Instantiation> found;
        QList<const PythonScopeFacts *> open; ///< scopes being followed (cycles)
        int visits = 0;        ///< scopes followed so far (a call graph can fan out widely)
        bool reported = false; ///< a bound was hit (one diagnostic per setup call)
        bool stopped = false;  ///< a budget ran out: follow nothing more
    };

    QList<MethodPort> setupClassPorts(int id, const QList<PythonArgument> &arguments,
                                      int depth) const;
    void reachInstantiations(const PythonScopeFacts &scope, const QList<PythonArgument> *bound,
                             const QList<PythonParameter> *parameters, const QList<Evidence> &chain,
                             int depth, Reach *reach) const;

    const PythonDefinitionIndex &m_index;
    NodeTest m_isNode;
    HelperPorts m_helperPorts;
    mutable QList<Diagnostic> m_diagnostics; ///< bounds hit while following helpers
};

} // namespace rosarch
