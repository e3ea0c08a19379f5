#pragma once

#include "syntax/syntaxtree.h"

#include <QString>

#include <string_view>
#include <vector>

// Small readers over the tree-sitter-python grammar, shared by the Python analyzer parts.
namespace rosarch::py {

/// Whether Python text names the launch function: only then can it be a launch file (a cheap
/// test before any parse).
inline bool namesLaunchFunction(const QByteArray &content)
{
    return content.contains("generate_launch_description");
}

/// Like ts::walk (pre-order, return false to skip children) but with a tree cursor, which
/// visits wide nodes in linear time.
template <typename F> void walk(TSNode root, F &&visit)
{
    if (ts::isNull(root))
        return;
    TSTreeCursor cursor = ts_tree_cursor_new(root);
    int depth = 0;
    for (;;) {
        if (visit(ts_tree_cursor_current_node(&cursor)) &&
            ts_tree_cursor_goto_first_child(&cursor)) {
            ++depth;
            continue;
        }
        for (;;) {
            if (depth == 0) {
                ts_tree_cursor_delete(&cursor);
                return;
            }
            if (ts_tree_cursor_goto_next_sibling(&cursor))
                break;
            ts_tree_cursor_goto_parent(&cursor);
            --depth;
        }
    }
}

/// The i-th positional argument of a call (null node if absent or hidden behind *args).
TSNode positional(TSNode call, int index);
/// The value of the keyword argument `name` of a call (null node if absent).
TSNode keyword(const SyntaxTree &tree, TSNode call, std::string_view name);
/// The argument passed at position `index` or as keyword `name`.
TSNode argument(const SyntaxTree &tree, TSNode call, int index, std::string_view name);
/// For `a.b.c(...)` "c", for `f(...)` "f", "" otherwise.
std::string_view calleeName(const SyntaxTree &tree, TSNode call);
/// For `a.b.c(...)` the node `a.b`; null for a plain call.
TSNode calleeObject(TSNode call);
/// An identifier or a chain of attributes over an identifier (`a.b.c`).
bool isDottedName(TSNode node);
/// One formal parameter of a function definition.
struct Parameter
{
    QString name;
    TSNode defaultValue{};
};
/// All formal parameters, including `self`, in order (splats and separators skipped).
std::vector<Parameter> parameters(const SyntaxTree &tree, TSNode functionDefinition);
/// The function_definition or class_definition inside a possibly decorated definition.
TSNode undecorated(TSNode node);

} // namespace rosarch::py
