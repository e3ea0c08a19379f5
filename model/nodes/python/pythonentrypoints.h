#pragma once

#include "core/languageanalysis.h"
#include "nodes/python/pythondefinitionindex.h"

#include <QList>
#include <QStringList>

#include <functional>

namespace rosarch {

/// What each Python function starts (blueprint §1, "Nodes built in code"): the node classes it
/// constructs and the procedural nodes it builds, and those of the functions it calls,
/// kMaxBuilderDepth calls deep; a construction in a loop over a list of literals is one node
/// per item.
class PythonEntryPoints
{
public:
    /// `isNode(cls)`: class `cls` is a node class; `procedurals(scope)`: the qualified names of
    /// the procedural nodes built in `scope`; `construction(cls, call)`: class `cls` as `call`
    /// builds it.
    PythonEntryPoints(const PythonDefinitionIndex &index, std::function<bool(int)> isNode,
                      std::function<QStringList(const PythonScopeFacts *)> procedurals,
                      std::function<NodeConstruction(int, const PythonCall &)> construction);

    /// One entry point per named function that starts a node. A call not followed because of
    /// the bound, to a function that builds a node itself, is a `builder-depth` note.
    void addEntryPoints(LanguageAnalysis *out) const;

    /// Calls to functions are followed this deep.
    static constexpr int kMaxBuilderDepth = 3;

private:
    QStringList startedNodes(int function, int depth, QList<int> *visited,
                             QList<Evidence> *boundsHit) const;
    void addConstructions(int function, int depth, QList<int> *visited,
                          QList<NodeConstruction> *out) const;
    /// Whether `function` itself constructs a node or builds a procedural one.
    bool buildsNode(int function) const;

    const PythonDefinitionIndex &m_index;
    std::function<bool(int)> m_isNode;
    std::function<QStringList(const PythonScopeFacts *)> m_procedurals;
    std::function<NodeConstruction(int, const PythonCall &)> m_construction;
};

} // namespace rosarch
