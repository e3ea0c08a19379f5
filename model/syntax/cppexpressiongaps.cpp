// Valid C++ the grammar cannot read inside functions and parameter lists
// (cppsyntax::blankGrammarGaps).
#include "syntax/cppexpressiongaps.h"
#include "syntax/cppcodescan.h"
#include "syntax/cppmacrogaps.h"

#include <cstring>
#include <vector>

namespace rosarch::cppsyntax::expressions {

using namespace scan;
using macros::atStatementStart;
using macros::isMacroWord;

bool isMacroLikeWord(std::string_view word)
{
    if (word.find('_') == std::string_view::npos)
        return false;
    int capitals = 0;
    for (const char c : word) {
        capitals = c >= 'A' && c <= 'Z' ? capitals + 1 : 0;
        if (capitals == 3)
            return true;
    }
    return false;
}

namespace {

bool isOneOf(std::string_view w, std::initializer_list<const char *> words)
{
    for (const char *k : words)
        if (w == k)
            return true;
    return false;
}

bool isKeyword(std::string_view w)
{
    return isOneOf(w, {"if",      "for",      "while",     "switch",        "catch",
                       "return",  "sizeof",   "alignof",   "decltype",      "typeid",
                       "new",     "delete",   "throw",     "static_assert", "noexcept",
                       "alignas", "co_await", "co_return", "co_yield",      "do",
                       "else",    "case",     "default",   "goto",          "try",
                       "using",   "template", "typename",  "operator"});
}

/// Words that begin a declaration's type or specifiers.
bool beginsDeclaration(std::string_view w)
{
    return isOneOf(w, {"void", "int", "bool", "char", "short", "long", "unsigned", "signed",
                       "float", "double", "auto", "static", "inline", "const", "constexpr",
                       "virtual", "explicit", "extern", "template"});
}

/// The `}` closing the `{` at `open`, -1 when none before `limit`.
qsizetype closingBrace(const QByteArray &code, qsizetype open, qsizetype limit)
{
    int depth = 0;
    for (qsizetype i = open; i < code.size() && i < limit; ++i) {
        depth += code.at(i) == '{' ? 1 : code.at(i) == '}' ? -1 : 0;
        if (depth == 0)
            return i;
    }
    return -1;
}

/// Whether the innermost block at an offset is a function body or a block in one, for offsets
/// asked in ascending order: one pass over the braces, however many words ask.
class Blocks
{
public:
    explicit Blocks(const QByteArray &code) : m_code(code) {}

    bool functionBodyAt(qsizetype at)
    {
        for (; m_next < at && m_next < m_code.size(); ++m_next) {
            const char c = m_code.at(m_next);
            if (c == '{')
                m_stack.push_back(opensBody(m_next));
            else if (c == '}' && !m_stack.empty())
                m_stack.pop_back();
        }
        return !m_stack.empty() && m_stack.back();
    }

private:
    /// The `{` follows a `)`, another block's brace or a statement, or `else`, `do`, `try` or a
    /// qualifier (not `final`, which ends a class head too).
    bool opensBody(qsizetype brace) const
    {
        const qsizetype before = previousCode(m_code, brace);
        if (before < 0)
            return false;
        if (std::strchr(");{}", m_code.at(before)))
            return true;
        return isOneOf(wordEndingAt(m_code, before + 1),
                       {"else", "do", "try", "const", "override", "noexcept", "mutable"});
    }

    const QByteArray &m_code;
    qsizetype m_next = 0;
    std::vector<bool> m_stack;
};

class Rewriter
{
public:
    Rewriter(QByteArray &code, char *data)
        : m_code(code), m_data(data), m_n(code.size()), m_blocks(code)
    {
    }

    void run()
    {
        if (m_code.contains('='))
            unnamedParameterDefaults();
        if (m_code.contains(';'))
            statementsInMacroArguments();
        if (m_code.contains('['))
            bracedCaptures();
        words();
    }

private:
    void set(qsizetype from, qsizetype to, char c)
    {
        for (qsizetype i = from; i < to; ++i)
            if (m_code.at(i) != '\n' && m_code.at(i) != '\r') {
                m_data[i] = c;
                m_code[i] = c;
            }
    }

    // `const void * = 0`: a `=` after a `*` or `&` with a space between, which no expression
    // has; blanked up to the parameter's end.
    void unnamedParameterDefaults()
    {
        for (qsizetype i = 1; i + 1 < m_n; ++i) {
            if (m_code.at(i) != '=' || m_code.at(i + 1) == '=')
                continue;
            const qsizetype before = previousCode(m_code, i);
            if (before < 0 || before == i - 1 || !std::strchr("*&", m_code.at(before)))
                continue;
            if (wordEndingAt(m_code, previousCode(m_code, before) + 1) == "operator")
                continue;
            // up to the parameter's end: `,`, `)`, or the `>` that closes a template's
            // parameters (`typename std::enable_if<B>::type * = nullptr>`)
            qsizetype end = i + 1;
            for (int depth = 0, angles = 0; end < m_n && end - i < 512; ++end) {
                const char c = m_code.at(end);
                if (depth == 0 && angles == 0 && std::strchr(",);{>", c))
                    break;
                depth += nesting(c);
                if (c == '<' && isIdentifierChar(m_code.at(previousCode(m_code, end))))
                    ++angles;
                else if (c == '>' && angles > 0)
                    --angles;
            }
            if (end < m_n && std::strchr(",)>", m_code.at(end)))
                set(i, end, ' ');
        }
    }

    // `LOG_STREAM(a << b;)`: a `;` before the `)` of a macro call.
    void statementsInMacroArguments()
    {
        for (qsizetype i = 0; i < m_n; ++i) {
            if (m_code.at(i) != ';')
                continue;
            const qsizetype next = nextCode(m_code, i + 1);
            if (next >= m_n || m_code.at(next) != ')')
                continue;
            int depth = 0;
            for (qsizetype k = i - 1; k >= 0 && i - k < 4096; --k) {
                depth += nesting(m_code.at(k));
                if (depth == 1) { // the `(` around the `;`
                    if (m_code.at(k) == '(' &&
                        isMacroWord(wordEndingAt(m_code, previousCode(m_code, k) + 1)))
                        set(i, i + 1, ' ');
                    break;
                }
            }
        }
    }

    // `[this, p{std::move(p)}] {`: the grammar reads `p = std::move(p)` only.
    void bracedCaptures()
    {
        for (qsizetype open = 0; open < m_n; ++open) {
            if (m_code.at(open) != '[')
                continue;
            const qsizetype before = previousCode(m_code, open);
            if (before >= 0 && !std::strchr("(,={;}", m_code.at(before)) &&
                wordEndingAt(m_code, before + 1) != "return")
                continue;
            qsizetype close = open;
            for (int depth = 0; close < m_n && close - open < 1024; ++close) {
                depth += m_code.at(close) == '[' ? 1 : m_code.at(close) == ']' ? -1 : 0;
                if (depth == 0)
                    break;
            }
            const qsizetype after = close < m_n ? nextCode(m_code, close + 1) : m_n;
            if (after >= m_n || !(m_code.at(after) == '(' || m_code.at(after) == '{' ||
                                  isWordAt(m_code, after, "mutable")))
                continue;
            for (qsizetype i = open + 1; i < close; ++i) {
                if (m_code.at(i) != '{' || !isIdentifierChar(m_code.at(previousCode(m_code, i))))
                    continue;
                const qsizetype name = previousCode(m_code, i) + 1;
                const std::string_view word = wordEndingAt(m_code, name);
                const qsizetype lead = previousCode(m_code, name - qsizetype(word.size()));
                const qsizetype end = closingBrace(m_code, i, close);
                if (lead < 0 || !std::strchr("[,", m_code.at(lead)) || end < 0)
                    continue;
                set(i, i + 1, '=');
                set(end, end + 1, ' ');
                i = end;
            }
            open = close;
        }
    }

    // A built-in type as an argument, `Q_ARG(int, level)`: only a macro takes one.
    void typeArguments(qsizetype open, qsizetype close)
    {
        for (const auto &[from, to] : builtinTypeArguments(m_code, open, close)) {
            const qsizetype first = nextCode(m_code, from);
            set(first, to, ' ');
            set(first, first + 1, '_');
        }
    }

    void words()
    {
        for (qsizetype i = 0; i < m_n;) {
            const std::string_view word = nextWord(m_code, &i);
            const qsizetype start = i - qsizetype(word.size());
            if (word.empty() || (word.front() >= '0' && word.front() <= '9'))
                continue;
            const qsizetype after = nextCode(m_code, i);
            const char following = after < m_n ? m_code.at(after) : ';';
            const qsizetype before = previousCode(m_code, start);
            const char preceding = before >= 0 ? m_code.at(before) : ';';
            const bool macro = isMacroWord(word);
            if (following == '(') {
                const qsizetype close = closingParen(m_code, after, after + 4096);
                if (close < 0)
                    continue;
                if (macro || word == "va_arg")
                    typeArguments(after, close);
                const qsizetype next = nextCode(m_code, close + 1);
                const qsizetype newline = m_code.indexOf('\n', close);
                const bool later = newline >= 0 && newline < next;
                // `{ PyVarObject_HEAD_INIT(nullptr, 0) "name", ...}`
                if ((macro || isMacroLikeWord(word)) && (preceding == '{' || preceding == ',') &&
                    later && next < m_n &&
                    (m_code.at(next) == '"' || isIdentifierChar(m_code.at(next)))) {
                    set(start, close + 1, ' ');
                    i = close + 1;
                    continue;
                }
                // `forEach(List, &items) {` in a function: a loop header of a macro.
                if (!isKeyword(word) && next < m_n && m_code.at(next) == '{' &&
                    atStatementStart(m_code, start) && m_blocks.functionBodyAt(start)) {
                    set(start, close + 1, ' ');
                    i = close + 1;
                }
                continue;
            }
            if (!isIdentifierChar(following) || (following >= '0' && following <= '9'))
                continue;
            // `OGRE_NEW T(...)`, `x = MACRO y`, `OGRE_DELETE this->p;`: a keyword's macro.
            if (macro) {
                const bool value =
                    (preceding == '=' || preceding == '?' ||
                     ((preceding == '(' || preceding == ',') && m_blocks.functionBodyAt(start)) ||
                     wordEndingAt(m_code, before + 1) == "return");
                const bool statement = isWordAt(m_code, after, "this") &&
                                       atStatementStart(m_code, start) &&
                                       m_blocks.functionBodyAt(start);
                if (value || statement)
                    set(start, i, ' ');
                continue;
            }
            // `NOINLINE void * operator new(...)`: an attribute in capitals on its line.
            bool capitals = word.size() >= 4;
            for (const char c : word)
                capitals = capitals && ((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'));
            const qsizetype lineEnd = m_code.indexOf('\n', start);
            if (capitals && atStatementStart(m_code, start) && (lineEnd < 0 || lineEnd > after)) {
                qsizetype k = after;
                if (beginsDeclaration(nextWord(m_code, &k)))
                    set(start, i, ' ');
            }
        }
    }

    QByteArray &m_code;
    char *m_data;
    const qsizetype m_n;
    Blocks m_blocks; ///< asked by words(), which moves forward
};

} // namespace

void rewriteExpressionGaps(QByteArray *code, char *data)
{
    Rewriter(*code, data).run();
}

} // namespace rosarch::cppsyntax::expressions
