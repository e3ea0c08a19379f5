#pragma once

#include "syntax/syntaxtree.h"

#include <vector>

namespace rosarch {

/// The functions and classes of one parsed Python file by byte range, so that "which function
/// or class encloses this node" needs no ts_node_parent (which rescans siblings from the root
/// and turns whole-file analyses quadratic on large files).
class PythonScopeIndex
{
public:
    explicit PythonScopeIndex(const SyntaxTree &tree);

    /// The nearest enclosing function_definition, null if a class body or the module comes first.
    TSNode enclosingFunction(TSNode node) const;
    /// The nearest enclosing class_definition (through methods and nested functions).
    TSNode enclosingClass(TSNode node) const;
    /// True when no function or class encloses `node`.
    bool isTopLevel(TSNode node) const;
    /// The nodes from `ancestor` down to `node` (both included), found by byte position.
    static std::vector<TSNode> pathBetween(TSNode ancestor, TSNode node);

private:
    struct Scope
    {
        uint32_t start = 0;
        uint32_t end = 0;
        TSNode node{};
        int parent = -1;
        bool isClass = false;
    };
    /// The innermost scope strictly enclosing `node`, or -1.
    int innermost(TSNode node) const;

    std::vector<Scope> m_scopes; ///< in document order
};

} // namespace rosarch
