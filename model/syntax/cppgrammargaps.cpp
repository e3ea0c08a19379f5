// Rewrites of valid C++ the tree-sitter grammar cannot read (cppsyntax::blankGrammarGaps).
#include "syntax/cppcodescan.h"
#include "syntax/cppexpressiongaps.h"
#include "syntax/cppgapstarts.h"
#include "syntax/cppmacrogaps.h"
#include "syntax/cppsyntax.h"

#include <QRegularExpression>

#include <cstring>
#include <optional>

namespace rosarch::cppsyntax {

namespace {

using namespace scan;
using macros::atStatementStart;
using macros::isMacroWord;

// The matches of `re` that start at one of `starts` (ascending), as globalMatch finds them when
// no match can start elsewhere: a start inside the previous match is passed over.
template <typename Apply>
void eachMatchAt(const QRegularExpression &re, const QString &text,
                 const std::vector<qsizetype> &starts, Apply apply)
{
    qsizetype end = -1;
    for (const qsizetype start : starts) {
        if (start < end)
            continue;
        const QRegularExpressionMatch m = re.match(text, start, QRegularExpression::NormalMatch,
                                                   QRegularExpression::AnchorAtOffsetMatchOption);
        if (!m.hasMatch())
            continue;
        apply(m);
        end = m.capturedEnd();
    }
}

// Explicit instantiations, `template class X<int>;`, `extern template void f<int>(int);`, at
// the start of a statement: they declare nothing the analysis reads.
template <typename Blank>
void blankExplicitInstantiations(const QByteArray &code, const std::vector<qsizetype> &templates,
                                 Blank blank)
{
    qsizetype from = 0;
    for (const qsizetype at : templates) {
        if (at < from)
            continue;
        from = at + 8;
        const qsizetype after = nextCode(code, at + 8);
        if (after >= code.size() || code.at(after) == '<') // a template declaration
            continue;
        qsizetype start = at;
        qsizetype before = previousCode(code, at);
        if (before >= 5 && isWordAt(code, before - 5, "extern")) {
            start = before - 5;
            before = previousCode(code, start);
        }
        if (before >= 0 && !std::strchr(";{}", code.at(before)))
            continue;
        // Up to the `;`; a brace means it was something else. Scans never overlap: the next
        // statement starts after this one's `;` or brace.
        qsizetype end = after;
        while (end < code.size() && !std::strchr(";{}", code.at(end)))
            ++end;
        if (end >= code.size() || code.at(end) != ';')
            continue;
        blank(start, end + 1);
        from = end + 1;
    }
}

// Braced default arguments, `= {}`, `= {1.0, 2.0}`, `= {{'.', 0}, {'x', 255}}`: an `=` right
// inside parentheses, after a name, `>`, `&` or `*`, then a balanced `{...}`, then `,` or `)`.
// The braces are bounded, and the scan goes on after them, so it stays linear.
template <typename Rewrite> void rewriteBracedDefaults(const QByteArray &code, Rewrite rewrite)
{
    std::vector<char> open;
    const qsizetype n = code.size();
    for (qsizetype i = 0; i < n; ++i) {
        const char c = code.at(i);
        if (c == '(' || c == '[' || c == '{') {
            open.push_back(c);
            continue;
        }
        if (c == ')' || c == ']' || c == '}') {
            if (!open.empty())
                open.pop_back();
            continue;
        }
        if (c != '=' || open.empty() || open.back() != '(')
            continue;
        if (std::strchr("=!<>+-*/%&|^", code.at(i - 1)) || (i + 1 < n && code.at(i + 1) == '='))
            continue; // a comparison or a compound assignment
        const qsizetype before = previousCode(code, i);
        if (before < 0 ||
            !(isIdentifierChar(code.at(before)) || std::strchr(">&*", code.at(before))))
            continue;
        const qsizetype brace = nextCode(code, i + 1);
        if (brace >= n || code.at(brace) != '{')
            continue;
        const qsizetype limit = std::min(n, brace + 4096);
        qsizetype close = brace;
        for (int depth = 0; close < limit && code.at(close) != ';'; ++close) {
            depth += code.at(close) == '{' ? 1 : code.at(close) == '}' ? -1 : 0;
            if (depth == 0)
                break;
        }
        if (close >= limit || code.at(close) != '}')
            continue;
        const qsizetype after = nextCode(code, close + 1);
        if (after >= n || (code.at(after) != ',' && code.at(after) != ')'))
            continue;
        rewrite(brace, close + 1);
        i = close; // the braces were balanced: `open` is as it was before them
    }
}

// True when the first argument of EXPECT_THROW(statement, exception) is a declaration
// (`GraphLoader loader(node)`, `auto tree = make()`), a block or several statements: the macro
// makes a statement of it, the grammar sees a call whose argument is not an expression.
bool isStatementArgument(const QByteArray &argument)
{
    const QByteArray a = argument.trimmed();
    if (a.contains(';') || a.startsWith('{'))
        return true;
    static const QRegularExpression declaration(QStringLiteral(
        "^(?:(?:const|static|constexpr|volatile)\\s+)*([A-Za-z_][\\w:]*)(?:\\s*<[^()]*>)?"
        "(?:\\s*[*&]+\\s*|\\s+)[A-Za-z_]\\w*\\s*(?:[({=]|$)"));
    const auto m = declaration.match(QString::fromLatin1(a));
    static const QStringList expressions = {QStringLiteral("new"),    QStringLiteral("delete"),
                                            QStringLiteral("sizeof"), QStringLiteral("co_await"),
                                            QStringLiteral("throw"),  QStringLiteral("not")};
    return m.hasMatch() && !expressions.contains(m.captured(1));
}

// The arguments of macros the grammar cannot read as a call: gtest's EXPECT_THROW family when
// its statement is not an expression, and Qt's SIGNAL(signature) / SLOT(signature), whose
// parameter types are not expressions. The call stays, with blank parentheses. Each scan
// resumes after the parentheses it matched, so the pass is linear.
template <typename Blank> void blankMacroArguments(const QByteArray &code, Blank blank)
{
    const qsizetype n = code.size();
    for (qsizetype i = 0; i < n;) {
        const std::string_view word = nextWord(code, &i);
        const bool signature = word == "SIGNAL" || word == "SLOT";
        const bool throws = (word.starts_with("EXPECT_") || word.starts_with("ASSERT_")) &&
                            word.ends_with("_THROW");
        if (!signature && !throws)
            continue;
        const qsizetype open = nextCode(code, i);
        if (open >= n || code.at(open) != '(')
            continue;
        qsizetype close = open;
        qsizetype comma = -1;
        for (int depth = 0; close < n; ++close) {
            const char c = code.at(close);
            if (c == '(' || c == '[' || c == '{')
                ++depth;
            else if ((c == ')' || c == ']' || c == '}') && --depth == 0)
                break;
            else if (c == ',' && depth == 1 && comma < 0)
                comma = close;
        }
        if (close >= n)
            return;
        i = close;
        if (code.at(close) != ')')
            continue;
        const qsizetype firstEnd = comma < 0 ? close : comma;
        if (throws && !isStatementArgument(code.mid(open + 1, firstEnd - open - 1)))
            continue;
        blank(open + 1, close);
    }
}

// `decltype(a, b)`, the SFINAE idiom `decltype((void)T::header, nullptr)` or `decltype(x,
// void())`: the grammar reads no comma expression there. Its type is that of the last operand,
// so everything up to the last comma at the top level is blanked.
template <typename Blank>
void blankDecltypeCommas(const QByteArray &code, const std::vector<qsizetype> &decltypes,
                         Blank blank)
{
    for (const qsizetype at : decltypes) {
        const qsizetype open = nextCode(code, at + 8);
        if (open >= code.size() || code.at(open) != '(')
            continue;
        const qsizetype close = closingParen(code, open, open + 4096);
        if (close < 0)
            continue;
        qsizetype comma = -1;
        for (qsizetype i = open + 1, depth = 0; i < close; ++i) {
            const char c = code.at(i);
            depth += nesting(c);
            if (c == ',' && depth == 0)
                comma = i;
        }
        if (comma >= 0)
            blank(open + 1, comma + 1);
    }
}

// An operator function named in a call, `x.operator()(a)`, `this->operator()(a)`, or at the
// start of a statement, `operator++();`: the grammar only reads an operator name where it is
// declared. The symbol becomes underscores (`x.operator__(a)`), a plain member call.
template <typename Rename>
void renameOperatorCalls(const QByteArray &code, const QString &text,
                         const std::vector<qsizetype> &starts, Rename rename)
{
    static const QRegularExpression call(
        QStringLiteral("\\boperator([ \\t]*(?:\\([ \\t]*\\)|\\[[ \\t]*\\]|[-+*/%^&|~!=<>]+))"
                       "\\s*\\("));
    eachMatchAt(call, text, starts, [&](const QRegularExpressionMatch &m) {
        const qsizetype before = previousCode(code, m.capturedStart());
        const bool member =
            before >= 0 && (code.at(before) == '.' ||
                            (code.at(before) == '>' && before > 0 && code.at(before - 1) == '-'));
        bool statement = before < 0 || std::strchr(";{}", code.at(before));
        if (statement) { // `operator++();`, not a declaration `operator()(int a);`
            const qsizetype close = closingParen(code, m.capturedEnd() - 1, code.size());
            const qsizetype after = close < 0 ? code.size() : nextCode(code, close + 1);
            statement = after < code.size() && code.at(after) == ';';
        }
        if (member || statement)
            rename(m.capturedStart(1), m.capturedEnd(1));
    });
}

// The `.` at `at` of `.*` follows an object (`obj`, `f()`, `a[i]`), not a number (`1.*x`).
bool isMemberAccessDot(const QString &text, qsizetype at)
{
    if (at == 0)
        return false;
    const QChar before = text.at(at - 1);
    if (before == u')' || before == u']' || before == u'>')
        return true;
    qsizetype start = at;
    while (start > 0 && (text.at(start - 1).isLetterOrNumber() || text.at(start - 1) == u'_'))
        --start;
    return start < at && !text.at(start).isDigit();
}

// Pointers to members: the grammar reads neither the types `void (C::*)(int)`,
// `std::string C::*` and `Member Class::*ptr;` nor the accesses `(obj->*pmf)(a)` and
// `obj.*(f.ptr)`. The class before `::*` is blanked (a plain pointer), `->*` becomes `->` (a
// plain member) and `.*` becomes ` *` (a product, which reads the same names).
template <typename Blank> void blankPointerToMembers(const QString &text, Blank blank)
{
    static const QRegularExpression type(
        QStringLiteral("(?:\\(\\s*|\\b)((?:::)?[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?"
                       "(?:\\s*::\\s*[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?)*\\s*::)\\s*\\*"));
    for (auto it = type.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        blank(m.capturedStart(1), m.capturedEnd(1));
    }
    for (qsizetype at = text.indexOf(QLatin1String("->*")); at >= 0;
         at = text.indexOf(QLatin1String("->*"), at + 3))
        blank(at + 2, at + 3);
    for (qsizetype at = text.indexOf(QLatin1String(".*")); at >= 0;
         at = text.indexOf(QLatin1String(".*"), at + 2))
        if (isMemberAccessDot(text, at))
            blank(at, at + 1);
}

// `using Ts::operator()...;`, the pack expansion that builds an overload set: the grammar
// reads the using-declaration without its `...`.
template <typename Blank>
void blankUsingPackExpansions(const QString &text, const std::vector<qsizetype> &starts,
                              Blank blank)
{
    static const QRegularExpression expansion(
        QStringLiteral("\\busing\\s[^;={}]*?(\\.\\.\\.)\\s*;"));
    eachMatchAt(expansion, text, starts, [&](const QRegularExpressionMatch &m) {
        blank(m.capturedStart(1), m.capturedEnd(1));
    });
}

// `typeid(int)`: the grammar reads typeid as a call, whose argument cannot be a built-in type.
template <typename Blank>
void blankTypeidTypes(const QString &text, const std::vector<qsizetype> &starts, Blank blank)
{
    static const QRegularExpression builtin(QStringLiteral(
        "\\btypeid\\s*\\(\\s*((?:const\\s+)?(?:unsigned|signed|short|long|int|char|float|double|"
        "bool|void|wchar_t|char8_t|char16_t|char32_t)\\b[^();{}]*)\\)"));
    eachMatchAt(builtin, text, starts, [&](const QRegularExpressionMatch &m) {
        blank(m.capturedStart(1), m.capturedEnd(1));
    });
}

// A reference initialised with parentheses, `const T & x(a.b);`, reads as a function returning
// a reference whose parameters are broken. When the parentheses hold a member access (`.` or
// `->`) and no default argument, they become braces: `const T & x{a.b};`.
template <typename Rewrite>
void bracedReferenceInitialisers(const QByteArray &code, const QString &text,
                                 const std::vector<qsizetype> &starts, Rewrite rewrite)
{
    static const QRegularExpression reference(QStringLiteral(
        "(?:^|[;{}])\\s*(?:const\\s+)?(?:::)?[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?"
        "(?:\\s*::\\s*[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?)*\\s*&\\s*[A-Za-z_]\\w*\\s*(\\()"));
    eachMatchAt(reference, text, starts, [&](const QRegularExpressionMatch &m) {
        const qsizetype open = m.capturedStart(1);
        const qsizetype close = closingParen(code, open, open + 4096);
        if (close < 0 || nextCode(code, close + 1) >= code.size() ||
            code.at(nextCode(code, close + 1)) != ';')
            return;
        bool access = false;
        bool defaulted = false;
        for (qsizetype i = open + 1, depth = 0; i < close; ++i) {
            const char c = code.at(i);
            depth += c == '(' ? 1 : c == ')' ? -1 : 0;
            const char prev = code.at(i - 1);
            const char next = code.at(i + 1);
            access = access ||
                     (c == '.' && prev != '.' && next != '.' && !std::isdigit(uchar(next))) ||
                     (c == '>' && prev == '-');
            defaulted =
                defaulted || (depth == 0 && c == '=' && next != '=' && !std::strchr("=!<>", prev));
        }
        if (access && !defaulted)
            rewrite(open, close);
    });
}

// A declaration as the unbraced body of `for`, `while` or `if`, `for (...) const auto r = f();`:
// the grammar wants a statement there. The declarator is blanked, `f();` stays.
template <typename Text, typename Blank>
void blankDeclarationBodies(const QByteArray &code, Text text, const std::vector<qsizetype> &heads,
                            Blank blank)
{
    static const QRegularExpression declaration(QStringLiteral(
        "\\G\\s*((?:const|constexpr)\\s+(?:auto\\b|[A-Za-z_][\\w:]*(?:<[^;{}()]*?>)?)"
        "|auto\\b)\\s*[&*]*\\s*[A-Za-z_]\\w*\\s*=(?!=)"));
    // `\\b(?:for|while|if)\\s*\\(` matches at each head; the matches never overlap.
    for (const qsizetype open : heads) {
        const qsizetype close = closingParen(code, open, code.size());
        if (close < 0)
            continue;
        // The declaration starts with `const`, `constexpr` or `auto`: only then is it tried.
        qsizetype end = skipRegexSpaces(code, close + 1);
        const qsizetype start = end;
        while (end < code.size() && isIdentifierChar(code.at(end)))
            ++end;
        const std::string_view word(code.constData() + start, size_t(end - start));
        if (word != "const" && word != "constexpr" && word != "auto")
            continue;
        const QRegularExpressionMatch d = declaration.match(text(), close + 1);
        if (d.hasMatch())
            blank(d.capturedStart(1), d.capturedEnd());
    }
}

// True when an argument in the parentheses at [open, close] is a built-in type, `int`,
// `unsigned char`: no function takes that, only a macro.
bool hasBuiltinTypeArgument(const QByteArray &code, qsizetype open, qsizetype close)
{
    return !builtinTypeArguments(code, open, close).empty();
}

// A macro invocation that stands alone, without a `;`, at the start of a statement or member:
// `EIGEN_MAKE_ALIGNED_OPERATOR_NEW`, `ROBIN_HOOD_TRACE(this)`,
// `BOOST_GEOMETRY_REGISTER_POINT_3D(P, double, cs::cartesian, x, y, z)`. A name in capitals
// with an underscore, its balanced arguments if any, then, on a later line, the next
// declaration or statement (a name) or the end of the block: nothing C++ reads that way.
// A `{`, `;`, `(`, an operator or a `:` after it means it was a function header (`TEST(a, b)
// {`), a statement or an expression, and it stays, unless, before a `;`, an argument is a
// built-in type (`ROBIN_HOOD_HASH_INT(unsigned char);`, `CHECK_FIELD(0, float, P, x);`): only
// a macro takes a type. The registration macros the analysis reads from the text stay.
template <typename Blank> void blankStandaloneMacros(const QByteArray &code, Blank blank)
{
    const qsizetype n = code.size();
    qsizetype previousEnd = -1;
    for (qsizetype i = 0; i < n;) {
        const std::string_view word = nextWord(code, &i);
        const qsizetype start = i - qsizetype(word.size());
        // Right after another standalone macro is a statement start too.
        if (!(isMacroWord(word) || expressions::isMacroLikeWord(word)) ||
            !(atStatementStart(code, start) || previousCode(code, start) == previousEnd - 1))
            continue;
        qsizetype end = i;
        const qsizetype open = nextCode(code, i);
        bool typeArgument = false;
        if (open < n && code.at(open) == '(') {
            const qsizetype close = closingParen(code, open, open + 4096);
            if (close < 0)
                continue;
            typeArgument = hasBuiltinTypeArgument(code, open, close);
            end = close + 1;
        }
        const qsizetype next = nextCode(code, end);
        const qsizetype newline = code.indexOf('\n', end);
        const bool later = newline >= 0 && newline < next;
        // A name alone before `}` closes a class only after a member, not as an enumerator.
        const qsizetype previous = previousCode(code, start); // -1 at the start of the file
        const bool ends = next >= n || (code.at(next) == '}' &&
                                        (end > i || previous < 0 || code.at(previous) != '{'));
        const bool declaration = typeArgument && next < n && code.at(next) == ';';
        if (!declaration && (!later || !(ends || isIdentifierChar(code.at(next)))))
            continue;
        if (word != "RCLCPP_COMPONENTS_REGISTER_NODE" && word != "PLUGINLIB_EXPORT_CLASS")
            blank(start, end);
        previousEnd = end;
        i = end;
    }
}

} // namespace

void blankGrammarGaps(QByteArray *source)
{
    QByteArray code = codeOnly(*source);
    char *data = source->data();
    auto blank = [&](qsizetype from, qsizetype to) {
        for (qsizetype i = from; i < to; ++i)
            if (data[i] != '\n' && data[i] != '\r')
                data[i] = ' ';
    };
    // First, so that the rewrites below see the statement that follows such a macro start
    // after a `;` or a brace, as it does once the macro is expanded.
    blankStandaloneMacros(code, [&](qsizetype from, qsizetype to) {
        blank(from, to);
        for (qsizetype i = from; i < to; ++i)
            if (code.at(i) != '\n' && code.at(i) != '\r')
                code[i] = ' ';
    });
    macros::rewriteMacroGaps(&code, data);
    expressions::rewriteExpressionGaps(&code, data);
    const GapStarts starts = findGapStarts(code);
    // Latin-1 maps every byte to one character, so match offsets are byte offsets. Made only
    // for a file with a place where an expression can match.
    std::optional<QString> latin1;
    auto text = [&]() -> const QString & {
        if (!latin1)
            latin1 = QString::fromLatin1(code);
        return *latin1;
    };
    if (!starts.news.empty() && contains(code, "new ")) {
        static const QRegularExpression pointerArray(
            QStringLiteral("\\bnew\\s+(?:const\\s+)?[A-Za-z_][\\w:]*\\s*(\\*+)\\s*\\["));
        eachMatchAt(pointerArray, text(), starts.news, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
        static const QRegularExpression valueInitialized(QStringLiteral(
            "\\bnew\\s+(?:const\\s+)?[A-Za-z_][\\w:]*[\\s*]*\\[[^\\]\\n;]*\\](\\s*\\(\\s*\\))"));
        eachMatchAt(valueInitialized, text(), starts.news, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
    }
    if (!starts.typenames.empty() && contains(code, "typename ")) {
        static const QRegularExpression constructed(
            QStringLiteral("(?:[=(,]|\\breturn)\\s*(typename)\\s+"
                           "[A-Za-z_]\\w*(?:<[^;{}()]*?>)?(?:::[A-Za-z_]\\w*(?:<[^;{}()]*?>)?)+"
                           "\\s*[({]"));
        const std::vector<qsizetype> at = typenameStarts(code, starts.typenames);
        if (!at.empty())
            eachMatchAt(constructed, text(), at, [&](const QRegularExpressionMatch &m) {
                blank(m.capturedStart(1), m.capturedEnd(1));
            });
    }
    if (!starts.members.empty()) {
        static const QRegularExpression member(
            QStringLiteral("(?:->|\\.)\\s*(template)\\s+[A-Za-z_]\\w*\\s*\\("));
        eachMatchAt(member, text(), starts.members, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
    }
    blankExplicitInstantiations(code, starts.templates, blank);
    if (code.contains('{')) {
        rewriteBracedDefaults(code, [&](qsizetype from, qsizetype to) {
            blank(from, to);
            data[from] = '0';
        });
    }
    if (starts.macroArguments) // the words it reads, each holding a text the gate looked for
        blankMacroArguments(code, blank);
    blankDecltypeCommas(code, starts.decltypes, blank);
    if (!starts.operators.empty()) {
        renameOperatorCalls(code, text(), starts.operators, [&](qsizetype from, qsizetype to) {
            std::fill(data + from, data + to, '_');
        });
    }
    if (starts.pointerToMember)
        blankPointerToMembers(text(), blank);
    if (!starts.usings.empty() && contains(code, "..."))
        blankUsingPackExpansions(text(), starts.usings, blank);
    if (!starts.typeids.empty())
        blankTypeidTypes(text(), starts.typeids, blank);
    if (!starts.references.empty()) {
        bracedReferenceInitialisers(code, text(), starts.references,
                                    [&](qsizetype open, qsizetype close) {
                                        data[open] = '{';
                                        data[close] = '}';
                                    });
    }
    blankDeclarationBodies(code, text, starts.heads, blank);
}

} // namespace rosarch::cppsyntax
