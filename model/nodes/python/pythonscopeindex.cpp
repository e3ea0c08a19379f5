#include "nodes/python/pythonscopeindex.h"

#include "syntax/pythonsyntax.h"

#include <algorithm>

namespace rosarch {

PythonScopeIndex::PythonScopeIndex(const SyntaxTree &tree)
{
    static const ts::TypeSet definitions(SyntaxTree::Grammar::Python,
                                         {"class_definition", "function_definition"});
    std::vector<int> open; // scopes enclosing the current position
    py::walk(tree.root(), [&](TSNode n) {
        const int kind = definitions.index(n);
        if (kind < 0)
            return true;
        const bool isClass = kind == 0;
        Scope s;
        s.start = ts_node_start_byte(n);
        s.end = ts_node_end_byte(n);
        s.node = n;
        s.isClass = isClass;
        while (!open.empty() && m_scopes[size_t(open.back())].end <= s.start)
            open.pop_back();
        s.parent = open.empty() ? -1 : open.back();
        open.push_back(int(m_scopes.size()));
        m_scopes.push_back(s);
        return true;
    });
}

int PythonScopeIndex::innermost(TSNode node) const
{
    const uint32_t start = ts_node_start_byte(node);
    const uint32_t end = ts_node_end_byte(node);
    // the last scope that starts at or before the node, then out through its parents
    auto it = std::upper_bound(m_scopes.begin(), m_scopes.end(), start,
                               [](uint32_t byte, const Scope &s) { return byte < s.start; });
    int i = int(it - m_scopes.begin()) - 1;
    while (i >= 0) {
        const Scope &s = m_scopes[size_t(i)];
        if (s.start <= start && end <= s.end && !ts_node_eq(s.node, node))
            return i;
        i = s.parent;
    }
    return -1;
}

TSNode PythonScopeIndex::enclosingFunction(TSNode node) const
{
    const int i = innermost(node);
    if (i < 0 || m_scopes[size_t(i)].isClass)
        return TSNode{};
    return m_scopes[size_t(i)].node;
}

TSNode PythonScopeIndex::enclosingClass(TSNode node) const
{
    for (int i = innermost(node); i >= 0; i = m_scopes[size_t(i)].parent)
        if (m_scopes[size_t(i)].isClass)
            return m_scopes[size_t(i)].node;
    return TSNode{};
}

bool PythonScopeIndex::isTopLevel(TSNode node) const
{
    return innermost(node) < 0;
}

std::vector<TSNode> PythonScopeIndex::pathBetween(TSNode ancestor, TSNode node)
{
    std::vector<TSNode> path{ancestor};
    const uint32_t start = ts_node_start_byte(node);
    const uint32_t end = ts_node_end_byte(node);
    TSTreeCursor cursor = ts_tree_cursor_new(ancestor);
    while (!ts_node_eq(path.back(), node)) {
        if (ts_tree_cursor_goto_first_child_for_byte(&cursor, start) < 0)
            break;
        // the first child that ends after `start`; later siblings when it is empty (MISSING)
        TSNode child = ts_tree_cursor_current_node(&cursor);
        while (!(ts_node_start_byte(child) <= start && end <= ts_node_end_byte(child))) {
            if (ts_node_start_byte(child) > start || !ts_tree_cursor_goto_next_sibling(&cursor)) {
                child = TSNode{};
                break;
            }
            child = ts_tree_cursor_current_node(&cursor);
        }
        if (ts::isNull(child))
            break;
        path.push_back(child);
    }
    ts_tree_cursor_delete(&cursor);
    return path;
}

} // namespace rosarch
