#include "syntax/syntaxtree.h"

#include <atomic>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <unordered_map>

extern "C" {
const TSLanguage *tree_sitter_python();
const TSLanguage *tree_sitter_cpp();
}

namespace rosarch {

namespace {
std::atomic<std::int64_t> parseTimeoutMicros{20 * 1000 * 1000};
}

void SyntaxTree::setParseTimeout(std::chrono::microseconds budget)
{
    parseTimeoutMicros = budget.count();
}

std::chrono::microseconds SyntaxTree::parseTimeout()
{
    return std::chrono::microseconds(parseTimeoutMicros.load());
}

void SyntaxTree::TreeDeleter::operator()(TSTree *t) const
{
    ts_tree_delete(t);
}

SyntaxTree::~SyntaxTree() = default;

namespace {

TSPoint pointAt(const QByteArray &source, qsizetype offset)
{
    TSPoint p{0, 0};
    qsizetype lineStart = 0;
    for (qsizetype i = 0; i < offset && i < source.size(); ++i) {
        if (source.at(i) == '\n') {
            ++p.row;
            lineStart = i + 1;
        }
    }
    p.column = uint32_t(offset - lineStart);
    return p;
}

} // namespace

SyntaxTree SyntaxTree::parse(Grammar grammar, QByteArray source, QString file)
{
    return parseWith(grammar, std::move(source), std::move(file), nullptr);
}

SyntaxTree SyntaxTree::reparse(const SyntaxTree &previous, QByteArray source, qsizetype begin,
                               qsizetype end)
{
    if (!previous.m_tree || source.size() != previous.m_source.size() || begin < 0 ||
        end > source.size() || begin > end)
        return parse(previous.m_grammar, std::move(source), previous.m_file);
    TSTree *edited = ts_tree_copy(previous.m_tree.get());
    TSInputEdit edit;
    edit.start_byte = uint32_t(begin);
    edit.old_end_byte = uint32_t(end);
    edit.new_end_byte = uint32_t(end);
    edit.start_point = pointAt(source, begin);
    edit.old_end_point = pointAt(source, end);
    edit.new_end_point = edit.old_end_point;
    ts_tree_edit(edited, &edit);
    SyntaxTree tree = parseWith(previous.m_grammar, std::move(source), previous.m_file, edited);
    ts_tree_delete(edited);
    return tree;
}

SyntaxTree SyntaxTree::parseWith(Grammar grammar, QByteArray source, QString file,
                                 const TSTree *old)
{
    SyntaxTree tree;
    tree.m_grammar = grammar;
    tree.m_source = std::move(source);
    tree.m_file = std::move(file);
    TSParser *parser = ts_parser_new();
    ts_parser_set_language(parser,
                           grammar == Grammar::Python ? tree_sitter_python() : tree_sitter_cpp());
    // A generous bound so that pathological input cannot stall a stage.
    ts_parser_set_timeout_micros(parser, uint64_t(parseTimeoutMicros.load()));
    tree.m_tree.reset(ts_parser_parse_string(parser, old, tree.m_source.constData(),
                                             uint32_t(tree.m_source.size())));
    // A parse that timed out leaves the parser holding the suspended parse: drop it before
    // the parser goes (the tree is null, and syntaxErrors() says the file was not parsed).
    if (!tree.m_tree)
        ts_parser_reset(parser);
    ts_parser_delete(parser);
    return tree;
}

TSNode SyntaxTree::root() const
{
    if (!m_tree) {
        TSNode null{};
        return null;
    }
    return ts_tree_root_node(m_tree.get());
}

std::string_view SyntaxTree::view(TSNode node) const
{
    if (ts_node_is_null(node))
        return {};
    const uint32_t start = ts_node_start_byte(node);
    const uint32_t end = ts_node_end_byte(node);
    if (end > uint32_t(m_source.size()) || start > end)
        return {};
    return std::string_view(m_source.constData() + start, end - start);
}

QString SyntaxTree::text(TSNode node) const
{
    const std::string_view v = view(node);
    return QString::fromUtf8(v.data(), qsizetype(v.size()));
}

Evidence SyntaxTree::evidence(TSNode node) const
{
    Evidence e;
    if (ts_node_is_null(node))
        return e;
    const TSPoint s = ts_node_start_point(node);
    const TSPoint f = ts_node_end_point(node);
    e.file = m_file;
    e.line = int(s.row) + 1;
    e.column = int(s.column) + 1;
    e.endLine = int(f.row) + 1;
    e.endColumn = int(f.column) + 1;
    return e;
}

QList<Diagnostic> SyntaxTree::syntaxErrors(int limit) const
{
    QList<Diagnostic> out;
    TSNode r = root();
    if (ts_node_is_null(r)) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Error;
        d.code = QStringLiteral("parse-failed");
        d.message = QStringLiteral("%1 was not analysed: parsing it took longer than the time "
                                   "budget of %2 s per file.")
                        .arg(m_file)
                        .arg(double(parseTimeoutMicros.load()) / 1e6);
        d.evidence = Evidence::startOf(m_file);
        out.append(d);
        return out;
    }
    if (!ts_node_has_error(r))
        return out;
    ts::walk(r, [&](TSNode n) {
        if (out.size() >= limit)
            return false;
        if (!ts_node_has_error(n))
            return false;
        if (ts::is(n, "ERROR") || ts_node_is_missing(n)) {
            Diagnostic d;
            d.severity = m_grammar == Grammar::Python ? Diagnostic::Severity::Error
                                                      : Diagnostic::Severity::Warning;
            d.code = QStringLiteral("syntax-error");
            d.evidence = evidence(n);
            d.message =
                ts_node_is_missing(n)
                    ? QStringLiteral("Syntax error in %1 at line %2: missing %3; the rest of the "
                                     "file is still analysed.")
                          .arg(m_file)
                          .arg(d.evidence.line)
                          .arg(QString::fromUtf8(ts_node_type(n)))
                    : QStringLiteral(
                          "Syntax error in %1 at line %2; the rest of the file is still analysed.")
                          .arg(m_file)
                          .arg(d.evidence.line);
            out.append(d);
            return false;
        }
        return true;
    });
    return out;
}

namespace ts {
namespace {

// A grammar's symbol names as views: ts_node_type gives a C string, and the view of it
// measured its length on every call (the analyzers ask for the type of nearly every node).
class SymbolNames
{
public:
    explicit SymbolNames(const TSLanguage *language) : m_language(language)
    {
        const uint32_t count = ts_language_symbol_count(language);
        m_names.reserve(count);
        for (uint32_t s = 0; s < count; ++s) {
            const char *name = ts_language_symbol_name(language, TSSymbol(s));
            m_names.emplace_back(name ? std::string_view(name) : std::string_view());
        }
    }
    const TSLanguage *language() const { return m_language; }
    // ts_node_symbol is the public symbol of the node's (alias) symbol, which has the name
    // ts_node_type gives; the error symbols lie outside the table.
    std::string_view name(TSNode n) const
    {
        const TSSymbol symbol = ts_node_symbol(n);
        return symbol < m_names.size() ? m_names[symbol] : std::string_view(ts_node_type(n));
    }

private:
    const TSLanguage *m_language;
    std::vector<std::string_view> m_names;
};

// A grammar's field ids by name. ts_node_child_by_field_name looks the name up by comparing it
// with every field name of the grammar on each call; field() runs on most nodes the analyzers
// visit, so each grammar's names are hashed once.
class FieldIds
{
public:
    explicit FieldIds(const TSLanguage *language) : m_language(language)
    {
        const uint32_t count = ts_language_field_count(language);
        for (TSFieldId id = 1; id <= count; ++id) {
            const char *name = ts_language_field_name_for_id(language, id);
            if (name)
                m_ids.emplace(std::string_view(name), id);
        }
    }
    const TSLanguage *language() const { return m_language; }
    TSFieldId id(std::string_view name) const
    {
        const auto it = m_ids.find(name);
        return it == m_ids.end() ? TSFieldId(0) : it->second;
    }

private:
    const TSLanguage *m_language;
    std::unordered_map<std::string_view, TSFieldId> m_ids;
};

} // namespace

std::string_view type(TSNode n)
{
    if (ts_node_is_null(n))
        return {};
    static const SymbolNames cpp(tree_sitter_cpp());
    static const SymbolNames python(tree_sitter_python());
    const TSLanguage *language = ts_tree_language(n.tree);
    if (language == cpp.language())
        return cpp.name(n);
    if (language == python.language())
        return python.name(n);
    return ts_node_type(n);
}

TSNode field(TSNode n, const char *name)
{
    if (ts_node_is_null(n))
        return n;
    static const FieldIds cpp(tree_sitter_cpp());
    static const FieldIds python(tree_sitter_python());
    const TSLanguage *language = ts_tree_language(n.tree);
    if (language == cpp.language())
        return ts_node_child_by_field_id(n, cpp.id(name));
    if (language == python.language())
        return ts_node_child_by_field_id(n, python.id(name));
    return ts_node_child_by_field_name(n, name, uint32_t(strlen(name)));
}

static const TSLanguage *languageOf(SyntaxTree::Grammar grammar)
{
    return grammar == SyntaxTree::Grammar::Python ? tree_sitter_python() : tree_sitter_cpp();
}

TSFieldId fieldId(SyntaxTree::Grammar grammar, std::string_view name)
{
    static const FieldIds cpp(tree_sitter_cpp());
    static const FieldIds python(tree_sitter_python());
    return (grammar == SyntaxTree::Grammar::Python ? python : cpp).id(name);
}

TypeSet::TypeSet(SyntaxTree::Grammar grammar, std::initializer_list<std::string_view> names)
    : m_language(languageOf(grammar)), m_names(names)
{
    const uint32_t count = ts_language_symbol_count(m_language);
    m_bySymbol.assign(count, -1);
    for (uint32_t s = 0; s < count; ++s) {
        const char *name = ts_language_symbol_name(m_language, TSSymbol(s));
        if (!name)
            continue;
        // The first of equal names, as indexOf would find it.
        for (size_t i = 0; i < m_names.size() && i < 127; ++i)
            if (m_names[i] == name) {
                m_bySymbol[s] = std::int8_t(i);
                break;
            }
    }
}

int TypeSet::slowIndex(TSNode n) const
{
    const std::string_view t = type(n);
    for (size_t i = 0; i < m_names.size() && i < 127; ++i)
        if (m_names[i] == t)
            return int(i);
    return -1;
}

// The children through a cursor, in one pass: ts_node_child(n, i) walks from the first
// child each time, which made wide nodes (an ERROR node holding a whole broken header)
// quadratic.
static std::vector<TSNode> childrenOf(TSNode n, bool namedOnly)
{
    std::vector<TSNode> out;
    if (ts_node_is_null(n))
        return out;
    out.reserve(namedOnly ? ts_node_named_child_count(n) : ts_node_child_count(n));
    TSTreeCursor cursor = ts_tree_cursor_new(n);
    if (ts_tree_cursor_goto_first_child(&cursor)) {
        do {
            const TSNode c = ts_tree_cursor_current_node(&cursor);
            if (!namedOnly || ts_node_is_named(c))
                out.push_back(c);
        } while (ts_tree_cursor_goto_next_sibling(&cursor));
    }
    ts_tree_cursor_delete(&cursor);
    return out;
}

std::vector<TSNode> namedChildren(TSNode n)
{
    return childrenOf(n, true);
}

std::vector<TSNode> children(TSNode n)
{
    return childrenOf(n, false);
}

std::vector<TSNode> fieldChildren(TSNode n, const char *name)
{
    std::vector<TSNode> out;
    if (ts_node_is_null(n))
        return out;
    TSTreeCursor cursor = ts_tree_cursor_new(n);
    if (ts_tree_cursor_goto_first_child(&cursor)) {
        do {
            const char *field = ts_tree_cursor_current_field_name(&cursor);
            if (field && strcmp(field, name) == 0)
                out.push_back(ts_tree_cursor_current_node(&cursor));
        } while (ts_tree_cursor_goto_next_sibling(&cursor));
    }
    ts_tree_cursor_delete(&cursor);
    return out;
}

std::vector<TSNode> fieldChildren(TSNode n, TSFieldId id)
{
    std::vector<TSNode> out;
    if (ts_node_is_null(n) || id == 0)
        return out;
    TSTreeCursor cursor = ts_tree_cursor_new(n);
    if (ts_tree_cursor_goto_first_child(&cursor)) {
        do {
            if (ts_tree_cursor_current_field_id(&cursor) == id)
                out.push_back(ts_tree_cursor_current_node(&cursor));
        } while (ts_tree_cursor_goto_next_sibling(&cursor));
    }
    ts_tree_cursor_delete(&cursor);
    return out;
}

TSNode ancestor(TSNode n, std::initializer_list<std::string_view> types)
{
    for (TSNode p = ts_node_parent(n); !ts_node_is_null(p); p = ts_node_parent(p)) {
        for (auto t : types)
            if (type(p) == t)
                return p;
    }
    TSNode null{};
    return null;
}
} // namespace ts

} // namespace rosarch
