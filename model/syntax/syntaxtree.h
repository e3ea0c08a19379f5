#pragma once

#include "core/diagnostic.h"
#include "core/evidence.h"

#include <QByteArray>
#include <QList>
#include <QString>

#include <tree_sitter/api.h>

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string_view>
#include <vector>

namespace rosarch {

/// A parsed source file: owns the tree-sitter tree and the bytes it points into.
/// Move-only; nodes (TSNode) are valid while the SyntaxTree lives.
class SyntaxTree
{
public:
    enum class Grammar
    {
        Python,
        Cpp
    };

    /// Parses `source`; never fails for text input (errors become ERROR nodes). A parse that
    /// runs longer than the parse time budget gives no tree (syntaxErrors() says so).
    static SyntaxTree parse(Grammar grammar, QByteArray source, QString file);
    /// Parses `source`, which is `previous`'s source with the bytes [begin, end) replaced by as
    /// many others (newlines kept), reusing what the edit did not touch (tree-sitter's
    /// incremental parse). Where the text has errors, tree-sitter's recovery may differ in
    /// detail from a full parse's; correct text gives the same tree.
    static SyntaxTree reparse(const SyntaxTree &previous, QByteArray source, qsizetype begin,
                              qsizetype end);

    /// The time budget of one parse, for every parse of the process (default 20 s).
    static void setParseTimeout(std::chrono::microseconds budget);
    static std::chrono::microseconds parseTimeout();

    SyntaxTree(SyntaxTree &&) noexcept = default;
    SyntaxTree &operator=(SyntaxTree &&) noexcept = default;
    ~SyntaxTree();

    TSNode root() const;
    const QString &file() const { return m_file; }
    const QByteArray &source() const { return m_source; }

    /// The node's source text (UTF-8 decoded).
    QString text(TSNode node) const;
    /// The node's source text without copying.
    std::string_view view(TSNode node) const;
    /// The node's range as evidence in this file (1-based lines and columns).
    Evidence evidence(TSNode node) const;
    /// One diagnostic per ERROR / MISSING region, at most `limit`. Errors in Python are
    /// reported as errors; in C++ as warnings, since unexpanded macros confuse any parser.
    QList<Diagnostic> syntaxErrors(int limit = 5) const;

private:
    SyntaxTree() = default;
    static SyntaxTree parseWith(Grammar grammar, QByteArray source, QString file,
                                const TSTree *old);
    struct TreeDeleter
    {
        void operator()(TSTree *t) const;
    };
    Grammar m_grammar = Grammar::Python;
    QByteArray m_source;
    QString m_file;
    std::unique_ptr<TSTree, TreeDeleter> m_tree;
};

// Small helpers over the tree-sitter C API, so analyzers read like the grammar.
namespace ts {
inline bool isNull(TSNode n)
{
    return ts_node_is_null(n);
}
/// The node's type name ("" for a null node).
std::string_view type(TSNode n);
inline bool is(TSNode n, std::string_view t)
{
    return type(n) == t;
}
TSNode field(TSNode n, const char *name);
/// The id of field `name` in `grammar` (0 when it has none): field(n, id) finds the child
/// without looking the name up, for the loops that run on every node.
TSFieldId fieldId(SyntaxTree::Grammar grammar, std::string_view name);
inline TSNode field(TSNode n, TSFieldId id)
{
    return ts_node_is_null(n) ? n : ts_node_child_by_field_id(n, id);
}

/// A few node types of one grammar, told apart by symbol rather than by comparing names:
/// a table from each symbol of the grammar to the index of its name in `names`, built once.
/// index(n) is `names`' index of type(n), -1 when it is none of them.
class TypeSet
{
public:
    TypeSet(SyntaxTree::Grammar grammar, std::initializer_list<std::string_view> names);
    int index(TSNode n) const
    {
        if (ts_node_is_null(n))
            return -1;
        const TSSymbol symbol = ts_node_symbol(n);
        if (symbol < m_bySymbol.size() && ts_tree_language(n.tree) == m_language)
            return m_bySymbol[symbol];
        return slowIndex(n); // ERROR and the other built-in symbols, another grammar
    }
    bool contains(TSNode n) const { return index(n) >= 0; }

private:
    int slowIndex(TSNode n) const;
    const TSLanguage *m_language;
    std::vector<std::string_view> m_names;
    std::vector<std::int8_t> m_bySymbol;
};
std::vector<TSNode> namedChildren(TSNode n);
std::vector<TSNode> children(TSNode n);
/// Every child under field `name` (a cursor: ts_node_field_name_for_child misreports
/// fields after unnamed children in tree-sitter 0.20).
std::vector<TSNode> fieldChildren(TSNode n, const char *name);
std::vector<TSNode> fieldChildren(TSNode n, TSFieldId id);
/// The nearest ancestor of one of the given types (null node if none).
TSNode ancestor(TSNode n, std::initializer_list<std::string_view> types);
/// Calls `visit` for `n` and every descendant in document order; return false to skip children.
/// Iterative (a tree cursor), so that no nesting depth can exhaust the stack, and linear.
template <typename F> void walk(TSNode n, F &&visit)
{
    if (isNull(n))
        return;
    TSTreeCursor cursor = ts_tree_cursor_new(n);
    for (;;) {
        const bool descend = visit(ts_tree_cursor_current_node(&cursor));
        if (descend && ts_tree_cursor_goto_first_child(&cursor))
            continue;
        // Up until a next sibling exists, never above `n`.
        bool moved = false;
        while (!moved) {
            if (ts_node_eq(ts_tree_cursor_current_node(&cursor), n))
                break;
            moved = ts_tree_cursor_goto_next_sibling(&cursor);
            if (!moved && !ts_tree_cursor_goto_parent(&cursor))
                break;
        }
        if (!moved)
            break;
    }
    ts_tree_cursor_delete(&cursor);
}
} // namespace ts

} // namespace rosarch
