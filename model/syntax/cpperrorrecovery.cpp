#include "syntax/cpperrorrecovery.h"

#include <QStringList>

#include <cctype>

#include <algorithm>
#include <optional>

namespace rosarch {

namespace {

bool isMacroName(std::string_view name)
{
    if (name.size() < 2)
        return false;
    if (name.substr(0, 3) == "PRI" || name.substr(0, 3) == "SCN")
        return true; // <cinttypes> format macros: "%" PRId64
    for (char c : name)
        if (!(std::isupper(uchar(c)) || std::isdigit(uchar(c)) || c == '_'))
            return false;
    return true;
}

bool isSpecifierWord(std::string_view word)
{
    for (const char *k : {"explicit", "virtual", "inline", "static", "constexpr", "override",
                          "final", "friend", "extern", "const"})
        if (word == k)
            return true;
    return false;
}

struct Range
{
    qsizetype begin = 0;
    qsizetype end = 0;
    bool operator==(const Range &) const = default;
};

struct Braces
{
    int net = 0;    ///< `{` minus `}`
    int lowest = 0; ///< the lowest running count: below 0 closes a block opened before
};

// Braces in [begin, end) outside comments, string and character literals.
Braces braces(const QByteArray &src, qsizetype begin, qsizetype end)
{
    Braces b;
    const char *d = src.constData();
    for (qsizetype i = begin; i < end; ++i) {
        const char c = d[i];
        if (c == '/' && i + 1 < end && d[i + 1] == '/') {
            while (i < end && d[i] != '\n')
                ++i;
        } else if (c == '/' && i + 1 < end && d[i + 1] == '*') {
            i += 2;
            while (i + 1 < end && !(d[i] == '*' && d[i + 1] == '/'))
                ++i;
            ++i;
        } else if (c == '"' || c == '\'') {
            ++i;
            while (i < end && d[i] != c && d[i] != '\n')
                i += d[i] == '\\' ? 2 : 1;
        } else if (c == '{') {
            ++b.net;
        } else if (c == '}') {
            --b.net;
            b.lowest = std::min(b.lowest, b.net);
        }
    }
    return b;
}

int lineOf(const QByteArray &src, qsizetype offset)
{
    return int(std::count(src.constData(), src.constData() + std::min(offset, src.size()), '\n')) +
           1;
}

// From the first non-blank character of `begin`'s line to the end of `end`'s line.
Range wholeLines(const QByteArray &src, qsizetype begin, qsizetype end)
{
    while (begin > 0 && src.at(begin - 1) != '\n')
        --begin;
    while (begin < end && (src.at(begin) == ' ' || src.at(begin) == '\t'))
        ++begin;
    while (end < src.size() && src.at(end) != '\n' && src.at(end) != '\r')
        ++end;
    return {begin, end};
}

Range rangeOf(TSNode n)
{
    return {qsizetype(ts_node_start_byte(n)), qsizetype(ts_node_end_byte(n))};
}

bool isStatement(std::string_view t)
{
    return (t.size() > 10 && t.substr(t.size() - 10) == "_statement" &&
            t != "compound_statement") ||
           t == "declaration" || t == "field_declaration" || t == "function_definition" ||
           t == "template_declaration" || t == "alias_declaration" || t == "using_declaration";
}

// What to blank around the first error, smallest first: the error itself, its lines, the
// statements and declarations around it (and their lines), the body of the function it is in.
std::vector<Range> candidates(const SyntaxTree &tree, TSNode error)
{
    const QByteArray &src = tree.source();
    std::vector<Range> out;
    const Range own = rangeOf(error);
    if (own.end > own.begin)
        out.push_back(own);
    out.push_back(wholeLines(src, own.begin, own.end));
    for (TSNode a = ts_node_parent(error); !ts::isNull(a); a = ts_node_parent(a)) {
        const auto t = ts::type(a);
        if (t == "translation_unit" || t == "field_declaration_list" || t == "declaration_list")
            break;
        if (isStatement(t)) {
            const Range r = rangeOf(a);
            out.push_back(r);
            out.push_back(wholeLines(src, r.begin, r.end));
        }
        if (t == "compound_statement" && (ts::is(ts_node_parent(a), "function_definition") ||
                                          ts::is(ts_node_parent(a), "lambda_expression"))) {
            const Range r = rangeOf(a);
            if (r.end - r.begin >= 2)
                out.push_back({r.begin + 1, r.end - 1});
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const Range &a, const Range &b) {
        return a.end - a.begin < b.end - b.begin;
    });
    std::vector<Range> unique;
    for (const Range &r : out) {
        if (r.end <= r.begin || std::find(unique.begin(), unique.end(), r) != unique.end())
            continue;
        if (lineOf(src, r.end) - lineOf(src, r.begin) >= CppErrorRecovery::kMaxBlankedLines)
            continue;
        unique.push_back(r);
    }
    return unique;
}

QByteArray blanked(const QByteArray &src, Range r)
{
    QByteArray out = src;
    for (qsizetype i = r.begin; i < r.end; ++i)
        if (out.at(i) != '\n' && out.at(i) != '\r')
            out[i] = ' ';
    return out;
}

bool isBlock(std::string_view t)
{
    return t == "compound_statement" || t == "field_declaration_list" || t == "declaration_list" ||
           t == "translation_unit";
}

// Where a blank must leave no error of its own: the function or class body it is in, or, at
// namespace level, up to the end of the next declaration.
Range scopeAround(const SyntaxTree &tree, Range r)
{
    TSNode block = ts_node_descendant_for_byte_range(tree.root(), uint32_t(r.begin),
                                                     uint32_t(std::max(r.begin, r.end - 1)));
    while (!ts::isNull(block) && !isBlock(ts::type(block)))
        block = ts_node_parent(block);
    if (ts::isNull(block))
        return {r.begin, qsizetype(tree.source().size())};
    if (ts::is(block, "compound_statement") || ts::is(block, "field_declaration_list"))
        return rangeOf(block);
    Range scope{r.begin, qsizetype(ts_node_end_byte(block))};
    for (TSNode child : ts::namedChildren(block)) {
        if (qsizetype(ts_node_start_byte(child)) >= r.end) {
            scope.end = qsizetype(ts_node_end_byte(child));
            break;
        }
    }
    return scope;
}

// A blank isolates an error when nothing in its scope is broken any more, except errors of
// their own further on that were there before.
bool isolates(const SyntaxTree &next, const std::vector<TSNode> &nextErrors,
              const std::vector<TSNode> &before, Range r, qsizetype from)
{
    const Range scope = scopeAround(next, r);
    for (const TSNode &e : nextErrors) {
        const qsizetype start = qsizetype(ts_node_start_byte(e));
        if (start < from || start < scope.begin || start >= scope.end)
            continue;
        if (start < r.end || ts_node_is_missing(e))
            return false;
        const bool old = std::any_of(before.begin(), before.end(), [&](const TSNode &o) {
            return qsizetype(ts_node_start_byte(o)) == start && !ts_node_is_missing(o);
        });
        if (!old)
            return false;
    }
    return true;
}

const TSNode *firstFrom(const std::vector<TSNode> &errors, qsizetype from)
{
    for (const TSNode &e : errors)
        if (qsizetype(ts_node_start_byte(e)) >= from)
            return &e;
    return nullptr;
}

// "part of line 7", "line 10", "lines 13-14".
QString linesOf(const QByteArray &src, Range r)
{
    const int first = lineOf(src, r.begin);
    const int last = lineOf(src, r.end);
    if (first != last)
        return QStringLiteral("lines %1-%2").arg(first).arg(last);
    return r == wholeLines(src, r.begin, r.end) ? QStringLiteral("line %1").arg(first)
                                                : QStringLiteral("part of line %1").arg(first);
}

} // namespace

SyntaxTree CppErrorRecovery::parse(QByteArray source, const QString &file,
                                   QList<Diagnostic> *diagnostics)
{
    SyntaxTree tree = SyntaxTree::parse(SyntaxTree::Grammar::Cpp, std::move(source), file);
    if (ts::isNull(tree.root()) || !ts_node_has_error(tree.root()))
        return tree;
    std::vector<TSNode> errors = realErrors(tree);
    // A file whose braces do not balance has a stray or missing brace somewhere: blanking it
    // is what repairs the structure, so candidates that bring the balance back come first.
    int balance = braces(tree.source(), 0, tree.source().size()).net;
    qsizetype from = 0;
    int parses = 0;
    QStringList dropped;
    Evidence firstError;
    while (parses < kMaxReparses) {
        const TSNode *first = firstFrom(errors, from);
        if (!first)
            break;
        const TSNode error = *first;
        std::optional<SyntaxTree> fallback;
        Range fallbackRange;
        bool fixed = false;
        for (const Range &r : candidates(tree, error)) {
            if (parses >= kMaxReparses)
                break;
            const Braces b = braces(tree.source(), r.begin, r.end);
            const bool repairs = balance != 0 && std::abs(balance - b.net) < std::abs(balance);
            if (!repairs && (b.net != 0 || b.lowest < 0))
                continue; // would unbalance a balanced file, or not help an unbalanced one
            if (!repairs && balance != 0 && fallback)
                continue;
            SyntaxTree next = SyntaxTree::reparse(tree, blanked(tree.source(), r), r.begin, r.end);
            ++parses;
            if (ts::isNull(next.root()))
                continue;
            std::vector<TSNode> nextErrors = realErrors(next);
            const TSNode *nextFirst = firstFrom(nextErrors, from);
            const bool better =
                nextErrors.size() < errors.size() &&
                (!nextFirst || qsizetype(ts_node_start_byte(*nextFirst)) >= r.end) &&
                isolates(next, nextErrors, errors, r, from);
            if (!better)
                continue;
            if (!repairs && balance != 0) { // keep looking for one that repairs the braces
                fallback.emplace(std::move(next));
                fallbackRange = r;
                continue;
            }
            if (dropped.isEmpty())
                firstError = tree.evidence(error);
            dropped.append(linesOf(tree.source(), r));
            balance -= b.net;
            tree = std::move(next);
            errors = std::move(nextErrors);
            fixed = true;
            break;
        }
        if (!fixed && fallback) {
            if (dropped.isEmpty())
                firstError = tree.evidence(error);
            dropped.append(linesOf(tree.source(), fallbackRange));
            tree = std::move(*fallback);
            errors = realErrors(tree);
            fixed = true;
        }
        if (!fixed) // give up on this one; the next error may still be isolated
            from = std::max(qsizetype(ts_node_end_byte(error)),
                            qsizetype(ts_node_start_byte(error)) + 1);
    }
    if (!dropped.isEmpty()) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.code = QStringLiteral("syntax-error");
        d.evidence = firstError;
        d.message =
            QStringLiteral("Syntax error in %1 at line %2; left out of the analysis so that "
                           "the rest parses: %3.")
                .arg(file)
                .arg(firstError.line)
                .arg(dropped.join(QStringLiteral(", ")));
        diagnostics->append(d);
    }
    return tree;
}

std::vector<TSNode> CppErrorRecovery::realErrors(const SyntaxTree &tree)
{
    std::vector<TSNode> out;
    const TSNode root = tree.root();
    if (ts::isNull(root) || !ts_node_has_error(root))
        return out;
    ts::walk(root, [&](TSNode n) {
        if (ts::is(n, "ERROR") || ts_node_is_missing(n)) {
            if (!isMacroArtifact(tree, n))
                out.push_back(n);
            return false;
        }
        return bool(ts_node_has_error(n));
    });
    return out;
}

bool CppErrorRecovery::isMacroArtifact(const SyntaxTree &tree, TSNode n)
{
    if (ts_node_is_missing(n)) {
        const std::string_view missing = ts::type(n);
        if (!missing.empty() && missing.front() == '#')
            return true;
        if (missing == ";") {
            // MACRO(args) without a semicolon: look at the text before the gap.
            const QByteArray &src = tree.source();
            qsizetype i = qsizetype(ts_node_start_byte(n)) - 1;
            while (i >= 0 && std::isspace(uchar(src.at(i))))
                --i;
            if (i < 0 || src.at(i) != ')')
                return false;
            for (int depth = 0; i >= 0; --i) {
                depth += src.at(i) == ')' ? 1 : src.at(i) == '(' ? -1 : 0;
                if (depth == 0)
                    break;
            }
            qsizetype end = i;
            while (end > 0 && std::isspace(uchar(src.at(end - 1))))
                --end;
            qsizetype begin = end;
            while (begin > 0 &&
                   (std::isalnum(uchar(src.at(begin - 1))) || src.at(begin - 1) == '_'))
                --begin;
            return end > begin &&
                   isMacroName(std::string_view(src.constData() + begin, size_t(end - begin)));
        }
        return false;
    }
    const auto kids = ts::namedChildren(n);
    if (kids.empty()) { // `EXPORT_MACRO ~Foo()`: the stray token becomes the error
        const TSNode previous = ts_node_prev_named_sibling(n);
        return !ts::isNull(previous) && isMacroName(tree.view(previous));
    }
    bool strings = true;
    bool words = true;
    bool macro = false;
    for (TSNode k : kids) {
        const bool name = ts::is(k, "identifier") || ts::is(k, "type_identifier");
        strings = strings && (ts::is(k, "string_literal") || ts::is(k, "concatenated_string"));
        words = words && name && (isMacroName(tree.view(k)) || isSpecifierWord(tree.view(k)));
        macro = macro || (name && isMacroName(tree.view(k)));
    }
    const TSNode next = ts_node_next_named_sibling(n);
    const TSNode previous = ts_node_prev_named_sibling(n);
    if (strings) // "%" PRId64: the string becomes the error, the macro its sibling
        return ts::is(next, "identifier") && isMacroName(tree.view(next));
    if (words && !macro) // `EXPORT_MACRO explicit Foo(...)`: the keyword becomes the error
        return !ts::isNull(previous) && isMacroName(tree.view(previous));
    return words;
}

} // namespace rosarch
