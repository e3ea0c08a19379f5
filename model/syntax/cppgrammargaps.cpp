// Rewrites of valid C++ the tree-sitter grammar cannot read (cppsyntax::blankGrammarGaps).
#include "cppcodescan.h"
#include "cppsyntax.h"

#include <QRegularExpression>

namespace rosarch::cppsyntax {

namespace {

using namespace scan;

// Explicit instantiations, `template class X<int>;`, `extern template void f<int>(int);`, at
// the start of a statement: they declare nothing the analysis reads.
template <typename Blank> void blankExplicitInstantiations(const QByteArray &code, Blank blank)
{
    for (qsizetype from = 0;;) {
        const qsizetype at = code.indexOf("template", from);
        if (at < 0)
            return;
        from = at + 8;
        if (!isWordAt(code, at, "template"))
            continue;
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
template <typename Blank> void blankDecltypeCommas(const QByteArray &code, Blank blank)
{
    for (qsizetype from = 0;;) {
        const qsizetype at = code.indexOf("decltype", from);
        if (at < 0)
            return;
        from = at + 8;
        const qsizetype open = nextCode(code, at + 8);
        if (!isWordAt(code, at, "decltype") || open >= code.size() || code.at(open) != '(')
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
void renameOperatorCalls(const QByteArray &code, const QString &text, Rename rename)
{
    static const QRegularExpression call(
        QStringLiteral("\\boperator([ \\t]*(?:\\([ \\t]*\\)|\\[[ \\t]*\\]|[-+*/%^&|~!=<>]+))"
                       "\\s*\\("));
    for (auto it = call.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
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
    }
}

// Pointers to members: the grammar reads neither the type `void (C::*)(int)` nor the call
// `(obj->*pmf)(a)`. The class before `::*` is blanked (a plain function pointer) and `->*`
// becomes `->` (a plain member).
template <typename Blank> void blankPointerToMembers(const QString &text, Blank blank)
{
    static const QRegularExpression type(
        QStringLiteral("\\(\\s*((?:::)?[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?"
                       "(?:\\s*::\\s*[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?)*\\s*::)\\s*\\*"));
    for (auto it = type.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        blank(m.capturedStart(1), m.capturedEnd(1));
    }
    for (qsizetype at = text.indexOf(QLatin1String("->*")); at >= 0;
         at = text.indexOf(QLatin1String("->*"), at + 3))
        blank(at + 2, at + 3);
}

// `using Ts::operator()...;`, the pack expansion that builds an overload set: the grammar
// reads the using-declaration without its `...`.
template <typename Blank> void blankUsingPackExpansions(const QString &text, Blank blank)
{
    static const QRegularExpression expansion(
        QStringLiteral("\\busing\\s[^;={}]*?(\\.\\.\\.)\\s*;"));
    for (auto it = expansion.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        blank(m.capturedStart(1), m.capturedEnd(1));
    }
}

// `typeid(int)`: the grammar reads typeid as a call, whose argument cannot be a built-in type.
template <typename Blank> void blankTypeidTypes(const QString &text, Blank blank)
{
    static const QRegularExpression builtin(QStringLiteral(
        "\\btypeid\\s*\\(\\s*((?:const\\s+)?(?:unsigned|signed|short|long|int|char|float|double|"
        "bool|void|wchar_t|char8_t|char16_t|char32_t)\\b[^();{}]*)\\)"));
    for (auto it = builtin.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        blank(m.capturedStart(1), m.capturedEnd(1));
    }
}

// A reference initialised with parentheses, `const T & x(a.b);`, reads as a function returning
// a reference whose parameters are broken. When the parentheses hold a member access (`.` or
// `->`) and no default argument, they become braces: `const T & x{a.b};`.
template <typename Rewrite>
void bracedReferenceInitialisers(const QByteArray &code, const QString &text, Rewrite rewrite)
{
    static const QRegularExpression reference(QStringLiteral(
        "(?:^|[;{}])\\s*(?:const\\s+)?(?:::)?[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?"
        "(?:\\s*::\\s*[A-Za-z_]\\w*(?:\\s*<[^;{}()]*?>)?)*\\s*&\\s*[A-Za-z_]\\w*\\s*(\\()"));
    for (auto it = reference.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const qsizetype open = m.capturedStart(1);
        const qsizetype close = closingParen(code, open, open + 4096);
        if (close < 0 || nextCode(code, close + 1) >= code.size() ||
            code.at(nextCode(code, close + 1)) != ';')
            continue;
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
    }
}

// A declaration as the unbraced body of `for`, `while` or `if`, `for (...) const auto r = f();`:
// the grammar wants a statement there. The declarator is blanked, `f();` stays.
template <typename Blank>
void blankDeclarationBodies(const QByteArray &code, const QString &text, Blank blank)
{
    static const QRegularExpression head(QStringLiteral("\\b(?:for|while|if)\\s*\\("));
    static const QRegularExpression declaration(QStringLiteral(
        "\\G\\s*((?:const|constexpr)\\s+(?:auto\\b|[A-Za-z_][\\w:]*(?:<[^;{}()]*?>)?)"
        "|auto\\b)\\s*[&*]*\\s*[A-Za-z_]\\w*\\s*=(?!=)"));
    for (auto it = head.globalMatch(text); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const qsizetype close = closingParen(code, m.capturedEnd() - 1, code.size());
        if (close < 0)
            continue;
        const QRegularExpressionMatch d = declaration.match(text, close + 1);
        if (d.hasMatch())
            blank(d.capturedStart(1), d.capturedEnd());
    }
}

bool isMacroWord(std::string_view word)
{
    bool underscore = false;
    for (char c : word) {
        if (!(std::isupper(uchar(c)) || std::isdigit(uchar(c)) || c == '_'))
            return false;
        underscore = underscore || c == '_';
    }
    return word.size() > 3 && underscore && !std::isdigit(uchar(word.front()));
}

// True when the code before `i` ends a statement or a member: `;`, `{`, `}`, or an access
// specifier's `:`.
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

// True when an argument in the parentheses at [open, close] is a built-in type, `int`,
// `unsigned char`: no function takes that, only a macro.
bool hasBuiltinTypeArgument(const QByteArray &code, qsizetype open, qsizetype close)
{
    static const QRegularExpression builtin(
        QStringLiteral("^\\s*(?:(?:const|unsigned|signed|short|long|int|char|float|double|bool|"
                       "void|wchar_t|char8_t|char16_t|char32_t|size_t|u?int(?:8|16|32|64)_t)\\b"
                       "\\s*)+[*&\\s]*$"));
    qsizetype from = open + 1;
    for (qsizetype i = open + 1, depth = 0; i <= close; ++i) {
        const char c = code.at(i);
        if (depth == 0 && (c == ',' || i == close)) {
            if (builtin.match(QString::fromLatin1(code.mid(from, i - from))).hasMatch())
                return true;
            from = i + 1;
        }
        depth += nesting(c);
    }
    return false;
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
        if (!isMacroWord(word) ||
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
        const bool ends = next >= n || (code.at(next) == '}' &&
                                        (end > i || code.at(previousCode(code, start)) != '{'));
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
    // Latin-1 maps every byte to one character, so match offsets are byte offsets.
    const QString text = QString::fromLatin1(code);
    auto each = [&](const QRegularExpression &re, auto apply) {
        for (auto it = re.globalMatch(text); it.hasNext();)
            apply(it.next());
    };
    const bool news = contains(code, "new ");
    const bool typenames = contains(code, "typename ");
    const bool templates = contains(code, "template");
    const bool braces = code.contains('{');
    const bool macros =
        contains(code, "_THROW") || contains(code, "SIGNAL") || contains(code, "SLOT");
    if (news) {
        static const QRegularExpression pointerArray(
            QStringLiteral("\\bnew\\s+(?:const\\s+)?[A-Za-z_][\\w:]*\\s*(\\*+)\\s*\\["));
        each(pointerArray, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
        static const QRegularExpression valueInitialized(QStringLiteral(
            "\\bnew\\s+(?:const\\s+)?[A-Za-z_][\\w:]*[\\s*]*\\[[^\\]\\n;]*\\](\\s*\\(\\s*\\))"));
        each(valueInitialized, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
    }
    if (typenames) {
        static const QRegularExpression constructed(
            QStringLiteral("(?:[=(,]|\\breturn)\\s*(typename)\\s+"
                           "[A-Za-z_]\\w*(?:<[^;{}()]*?>)?(?:::[A-Za-z_]\\w*(?:<[^;{}()]*?>)?)+"
                           "\\s*[({]"));
        each(constructed, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
    }
    if (templates) {
        static const QRegularExpression member(
            QStringLiteral("(?:->|\\.)\\s*(template)\\s+[A-Za-z_]\\w*\\s*\\("));
        each(member, [&](const QRegularExpressionMatch &m) {
            blank(m.capturedStart(1), m.capturedEnd(1));
        });
        blankExplicitInstantiations(code, blank);
    }
    if (braces) {
        rewriteBracedDefaults(code, [&](qsizetype from, qsizetype to) {
            blank(from, to);
            data[from] = '0';
        });
    }
    if (macros)
        blankMacroArguments(code, blank);
    if (contains(code, "decltype"))
        blankDecltypeCommas(code, blank);
    if (contains(code, "operator")) {
        renameOperatorCalls(code, text, [&](qsizetype from, qsizetype to) {
            std::fill(data + from, data + to, '_');
        });
    }
    if (contains(code, "::*") || contains(code, "->*"))
        blankPointerToMembers(text, blank);
    if (contains(code, "..."))
        blankUsingPackExpansions(text, blank);
    if (contains(code, "typeid"))
        blankTypeidTypes(text, blank);
    if (code.contains('&')) {
        bracedReferenceInitialisers(code, text, [&](qsizetype open, qsizetype close) {
            data[open] = '{';
            data[close] = '}';
        });
    }
    if (contains(code, "for") || contains(code, "while") || contains(code, "if"))
        blankDeclarationBodies(code, text, blank);
}

} // namespace rosarch::cppsyntax
