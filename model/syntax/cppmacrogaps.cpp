// Macros the grammar cannot read where they stand (cppsyntax::blankGrammarGaps).
#include "syntax/cppmacrogaps.h"
#include "syntax/cppcodescan.h"

#include <cstring>
#include <string>
#include <vector>

namespace rosarch::cppsyntax::macros {

using namespace scan;

bool isMacroWord(std::string_view word)
{
    bool underscore = false;
    for (char c : word) {
        if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_'))
            return false;
        underscore = underscore || c == '_';
    }
    return word.size() > 3 && underscore && !(word.front() >= '0' && word.front() <= '9');
}

bool atStatementStart(const QByteArray &code, qsizetype i)
{
    const qsizetype before = previousCode(code, i);
    if (before < 0 || std::strchr(";{}", code.at(before)))
        return true;
    if (code.at(before) != ':' || (before > 0 && code.at(before - 1) == ':'))
        return false;
    const qsizetype word = previousCode(code, before);
    return word >= 0 &&
           (isWordAt(code, word - 5, "public") || isWordAt(code, word - 6, "private") ||
            isWordAt(code, word - 8, "protected"));
}

namespace {

/// Read from the text by the analysis: never rewritten.
bool isRegistration(std::string_view word)
{
    return word == "RCLCPP_COMPONENTS_REGISTER_NODE" || word == "PLUGINLIB_EXPORT_CLASS" ||
           word == "CLASS_LOADER_REGISTER_CLASS";
}

/// Words after which a name in capitals with arguments is a call, not an annotation.
bool isExpressionKeyword(std::string_view w)
{
    for (const char *k : {"return", "throw", "case", "else", "do", "new", "delete", "co_return",
                          "co_yield", "sizeof", "alignof", "decltype", "typeid", "static_assert"})
        if (w == k)
            return true;
    return false;
}

/// Words that are a type or a specifier on their own: `int X(3);` declares X.
bool isTypeKeyword(std::string_view w)
{
    for (const char *k :
         {"int",    "long",      "short",    "char",      "bool",     "float",   "double",
          "auto",   "void",      "unsigned", "signed",    "size_t",   "static",  "extern",
          "inline", "constexpr", "mutable",  "volatile",  "typedef",  "using",   "struct",
          "class",  "enum",      "union",    "namespace", "template", "typename"})
        if (w == k)
            return true;
    return false;
}

/// Specifiers that begin a declaration of a function or a variable, not of a member's type.
bool isSpecifier(std::string_view w)
{
    return w == "inline" || w == "static" || w == "virtual" || w == "extern" || w == "constexpr" ||
           w == "friend" || w == "explicit";
}

/// True when the code before `i` starts a declaration: a statement start, the end of a
/// `template <...>` head, or a specifier (`explicit`, `static`, `virtual`, `inline`, `friend`).
bool atDeclarationStart(const QByteArray &code, qsizetype i)
{
    if (atStatementStart(code, i))
        return true;
    const qsizetype before = previousCode(code, i);
    if (before < 0)
        return true;
    if (code.at(before) == '>') { // `template <class T>`: back to its `<`
        int depth = 0;
        for (qsizetype k = before; k >= 0 && before - k < 1024; --k) {
            depth += code.at(k) == '>' ? 1 : code.at(k) == '<' ? -1 : 0;
            if (depth == 0)
                return wordEndingAt(code, previousCode(code, k) + 1) == "template";
        }
        return false;
    }
    const std::string_view w = wordEndingAt(code, before + 1);
    return w == "explicit" || w == "static" || w == "virtual" || w == "inline" || w == "friend";
}

/// For each `{`, whether it opens a scope of declarations only (a class, struct, union or
/// namespace body, `extern "C"`): the head before it names one of those and ends in neither
/// `)` nor an operator. Indexed by the brace's offset; the file itself is such a scope.
class Scopes
{
public:
    explicit Scopes(const QByteArray &code) : m_code(code) {}

    /// Moves to `at` (offsets only grow) and says whether the innermost scope there holds
    /// declarations only.
    bool declarationsAt(qsizetype at)
    {
        for (; m_next < at && m_next < m_code.size(); ++m_next) {
            const char c = m_code.at(m_next);
            if (c == '{')
                m_stack.push_back(opened(m_next));
            else if (c == '}' && !m_stack.empty())
                m_stack.pop_back();
        }
        return m_stack.empty() || m_stack.back().declarations;
    }
    /// The class whose body the last declarationsAt() was in ("" when none): its constructors
    /// are named for it.
    std::string_view className() const
    {
        return m_stack.empty() ? std::string_view() : m_stack.back().className;
    }

private:
    struct Scope
    {
        bool declarations = false;
        std::string className;
    };

    Scope opened(qsizetype brace) const
    {
        const qsizetype last = previousCode(m_code, brace);
        if (last < 0 || m_code.at(last) == ')' || m_code.at(last) == '=' ||
            m_code.at(last) == ',' || m_code.at(last) == '(' || m_code.at(last) == ']')
            return {};
        // The head: back to the previous statement's end, at most 512 bytes.
        qsizetype from = last;
        while (from > 0 && brace - from < 512 && !std::strchr(";{}", m_code.at(from - 1)))
            --from;
        for (qsizetype i = from; i < last + 1;) {
            const std::string_view w = nextWord(m_code, &i);
            if (w == "namespace" || w == "extern")
                return {true, {}};
            if (w == "class" || w == "struct" || w == "union") {
                std::string_view name = nextWord(m_code, &i);
                if (isMacroWord(name) && i < last + 1) // `class EXPORT_MACRO Name`
                    name = nextWord(m_code, &i);
                return {true, std::string(name)};
            }
            if (w.empty() || i > last + 1)
                break;
        }
        return {};
    }

    const QByteArray &m_code;
    qsizetype m_next = 0;
    std::vector<Scope> m_stack;
};

/// True when the `{` at `open` is a braced initializer, `{false};`: short, and a `;` follows its
/// `}`; a function body is no such thing.
bool bracedInitializerAt(const QByteArray &code, qsizetype open)
{
    int depth = 0;
    for (qsizetype i = open; i < code.size() && i - open < 512; ++i) {
        depth += code.at(i) == '{' ? 1 : code.at(i) == '}' ? -1 : 0;
        if (code.at(i) == ';' && depth > 0)
            return false;
        if (depth == 0) {
            const qsizetype next = nextCode(code, i + 1);
            return next < code.size() && code.at(next) == ';';
        }
    }
    return false;
}

/// True when the `)` at `close` ends a function's parameter list: its `(` follows a name (or a
/// template's `>`), not an operator, as a cast's `(double)` does.
bool closesParameterList(const QByteArray &code, qsizetype close)
{
    int depth = 0;
    for (qsizetype i = close; i >= 0 && close - i < 4096; --i) {
        depth -= nesting(code.at(i));
        if (depth == 0) {
            const qsizetype before = previousCode(code, i);
            if (before < 0)
                return false;
            if (code.at(before) == '>')
                return true;
            const std::string_view w = wordEndingAt(code, before + 1);
            return !w.empty() && !isExpressionKeyword(w) && !isTypeKeyword(w);
        }
    }
    return false;
}

/// True when the `)` at `close` ends the condition of `if`, `for`, `while` or `switch`: a
/// macro after it is the statement the condition guards, not an annotation.
bool afterControl(const QByteArray &code, qsizetype close)
{
    int depth = 0;
    for (qsizetype i = close; i >= 0 && close - i < 4096; --i) {
        depth -= nesting(code.at(i));
        if (depth == 0) {
            const std::string_view w = wordEndingAt(code, previousCode(code, i) + 1);
            return w == "if" || w == "for" || w == "while" || w == "switch";
        }
    }
    return true; // unbalanced: leave it
}

} // namespace

void rewriteMacroGaps(QByteArray *codeBuffer, char *data)
{
    QByteArray &code = *codeBuffer;
    const qsizetype n = code.size();
    auto set = [&](qsizetype from, qsizetype to, char c) {
        for (qsizetype i = from; i < to; ++i)
            if (code.at(i) != '\n' && code.at(i) != '\r') {
                data[i] = c;
                code[i] = c;
            }
    };
    Scopes scopes(code);
    for (qsizetype i = 0; i < n;) {
        const std::string_view word = nextWord(code, &i);
        const qsizetype start = i - qsizetype(word.size());
        if (isRegistration(word) || word.empty() || word.front() < 'A' || word.front() > 'Z')
            continue;
        const qsizetype before = previousCode(code, start);
        // A unit after a number: `0.01f METERS` (any word in capitals: nothing else can follow).
        if (before >= 0 && before == start - 2 && isIdentifierChar(code.at(before)) &&
            isMacroWord(std::string(word) + "_")) {
            qsizetype token = before;
            while (token > 0 && (isIdentifierChar(code.at(token - 1)) || code.at(token - 1) == '.'))
                --token;
            if (code.at(token) >= '0' && code.at(token) <= '9') {
                set(start, i, ' ');
                continue;
            }
        }
        if (!isMacroWord(word))
            continue;
        const qsizetype after = nextCode(code, i);
        // A constant joined to string literals by the preprocessor.
        const bool literalBefore = before >= 0 && before == start - 2 && code.at(before) == '"';
        const bool literalAfter = after == i + 1 && after < n && code.at(after) == '"';
        if (literalBefore || literalAfter) {
            if (literalBefore)
                set(start - 1, start, '+');
            if (literalAfter)
                set(i, i + 1, '+');
            continue;
        }
        // `void swap(value & x) PICOJSON_NOEXCEPT;`: an annotation without arguments after a
        // parameter list, before the declaration's end, body or `= 0`.
        if (!(after < n && code.at(after) == '(') && before >= 0 && code.at(before) == ')' &&
            after < n && std::strchr(";{=", code.at(after)) &&
            !(code.at(after) == '=' && after + 1 < n && code.at(after + 1) == '=') &&
            closesParameterList(code, before)) {
            set(start, i, ' ');
            continue;
        }
        const bool call = after < n && code.at(after) == '(';
        const qsizetype close = call ? closingParen(code, after, after + 4096) : -1;
        if (call && close < 0)
            continue;
        const qsizetype end = call ? close + 1 : i;
        const qsizetype next = nextCode(code, end);
        const char following = next < n ? code.at(next) : ';';
        const bool statementStart = atStatementStart(code, start);
        // A call with a `;` where only declarations stand.
        if (call && statementStart && following == ';' && scopes.declarationsAt(start)) {
            set(start, end, ' ');
            i = end;
            continue;
        }
        // An annotation after a declarator: after a parameter list, a qualifier, or a name that
        // follows a type; before the declaration's end or body.
        if (call && !statementStart && before >= 0 && std::strchr(";{=", following)) {
            const std::string_view previous =
                isIdentifierChar(code.at(before)) ? wordEndingAt(code, before + 1) : "";
            const qsizetype beforePrevious =
                previous.empty() ? -1 : previousCode(code, before + 1 - qsizetype(previous.size()));
            const bool afterDeclarator =
                (code.at(before) == ')' && !afterControl(code, before)) || previous == "const" ||
                previous == "override" || previous == "final" || previous == "noexcept" ||
                // `Type name_ MACRO(m);`, never a function `inline Type NAME(a) {`
                (!previous.empty() && (following != '{' || bracedInitializerAt(code, next)) &&
                 !isExpressionKeyword(previous) && !isTypeKeyword(previous) &&
                 beforePrevious >= 0 &&
                 (isIdentifierChar(code.at(beforePrevious)) || code.at(beforePrevious) == '>' ||
                  code.at(beforePrevious) == '*' || code.at(beforePrevious) == '&') &&
                 !isExpressionKeyword(wordEndingAt(code, beforePrevious + 1)) &&
                 !isSpecifier(wordEndingAt(code, beforePrevious + 1)));
            if (afterDeclarator && code.at(before) != '(' && code.at(before) != ',') {
                set(start, end, ' ');
                i = end;
                continue;
            }
        }
        // An attribute before a declaration, on its line: a type and more follow.
        if (next < n && isIdentifierChar(following) && code.indexOf('\n', end) > next &&
            atDeclarationStart(code, start) && scopes.declarationsAt(start)) {
            qsizetype k = next;
            const std::string_view type = nextWord(code, &k);
            const qsizetype more = nextCode(code, k);
            // `(` after the name: a constructor only, after `explicit` or named for its class
            // (`CAPS_TYPE f(` is a function returning a type named in capitals).
            const bool constructor =
                wordEndingAt(code, previousCode(code, start) + 1) == "explicit" ||
                (!type.empty() && type == scopes.className());
            const bool declaration =
                more < n &&
                (isIdentifierChar(code.at(more)) || std::strchr("&*<:", code.at(more)) ||
                 (call && code.at(more) == '{') || (code.at(more) == '(' && constructor));
            if (!declaration)
                continue;
            if (call && (type == "class" || type == "struct"))
                continue; // `MACRO(x) class Y`: rare; left as written
            if (call) {   // `ATTRIBUTE_ALIGNED16(class) Q`: the keyword stays
                const qsizetype inner = nextCode(code, after + 1);
                qsizetype k2 = inner;
                const std::string keyword(nextWord(code, &k2));
                set(start, end, ' ');
                if (keyword == "class" || keyword == "struct")
                    for (qsizetype c = 0; c < qsizetype(keyword.size()); ++c) {
                        data[inner + c] = keyword[size_t(c)];
                        code[inner + c] = keyword[size_t(c)];
                    }
            } else {
                set(start, end, ' ');
            }
            i = end;
        }
    }
}

} // namespace rosarch::cppsyntax::macros
