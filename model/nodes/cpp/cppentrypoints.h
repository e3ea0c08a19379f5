#pragma once

#include "core/languageanalysis.h"
#include "nodes/cpp/cppclassindex.h"
#include "nodes/cpp/cppconstructions.h"

#include <QHash>

#include <functional>

namespace rosarch {

/// What an executable's entry function starts (blueprint §1, "Nodes built in code"): the node
/// classes it constructs, and from `main()` those the free functions it calls construct
/// (`make_filter_line(options)`), kMaxBuilderDepth calls deep; a construction in a loop over a
/// list of literals is one node per item.
class CppEntryPoints
{
public:
    /// `ownName(cls)`: the name node class `cls` gives itself.
    CppEntryPoints(const CppClassIndex &index,
                   const QHash<QString, QList<CppClassIndex::FunctionRef>> &freeFunctionsByName,
                   const CppConstructions &constructions, std::function<QString(int)> ownName);

    /// The constructions `ref`'s function makes, and the classes, into `entry`; the calls not
    /// followed because of the bound into `boundsHit` (where a node is built past it).
    void addConstructions(const CppClassIndex::FunctionRef &ref, EntryPoint *entry,
                          QList<Evidence> *boundsHit) const;

    /// Calls to builder functions are followed this deep from `main()`.
    static constexpr int kMaxBuilderDepth = 4;

private:
    /// `depth` calls deep; `open` are the functions on the way.
    void addConstructions(const CppFunction &fn, const CppLinkContext &ctx, int depth,
                          QList<const CppFunction *> *open, EntryPoint *entry,
                          QList<Evidence> *boundsHit) const;

    const CppClassIndex &m_index;
    const QHash<QString, QList<CppClassIndex::FunctionRef>> &m_freeFunctionsByName;
    const CppConstructions &m_constructions;
    std::function<QString(int)> m_ownName;
};

} // namespace rosarch
