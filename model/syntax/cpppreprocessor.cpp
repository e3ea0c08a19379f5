#include "syntax/cpppreprocessor.h"

#include "syntax/cppconditionevaluator.h"

#include <string_view>
#include <vector>

namespace rosarch {

namespace {

bool isIdent(char c)
{
    return std::isalnum(uchar(c)) || c == '_';
}

// What the lexer carries from one line to the next.
struct LexState
{
    bool blockComment = false;
    bool rawString = false;
    QByteArray rawDelimiter;
};

// Scans [from, to) of one logical line: comments, string and character literals, raw strings.
// With `text`, appends the line as the preprocessor sees it (comments as one space, line
// continuations removed); `openComment` receives the start of a block comment still open at
// `to`, or stays -1.
void scan(const char *data, qsizetype from, qsizetype to, LexState &st, QByteArray *text,
          qsizetype *openComment)
{
    qsizetype blockStart = -1;
    auto append = [&](qsizetype a, qsizetype b) {
        if (text)
            text->append(data + a, b - a);
    };
    qsizetype i = from;
    while (i < to) {
        if (st.rawString) {
            const QByteArray end = ')' + st.rawDelimiter + '"';
            const qsizetype at = QByteArrayView(data + i, to - i).indexOf(end);
            const qsizetype stop = at < 0 ? to : i + at + end.size();
            append(i, stop);
            st.rawString = at < 0;
            i = stop;
            continue;
        }
        if (st.blockComment) {
            const qsizetype at = QByteArrayView(data + i, to - i).indexOf("*/");
            if (at < 0)
                break;
            st.blockComment = false;
            i += at + 2;
            if (text)
                text->append(' ');
            continue;
        }
        const char c = data[i];
        const char next = i + 1 < to ? data[i + 1] : '\0';
        if (c == '\\' && (next == '\n' || (next == '\r' && i + 2 < to && data[i + 2] == '\n'))) {
            i += next == '\n' ? 2 : 3;
        } else if (c == '/' && next == '/') {
            break;
        } else if (c == '/' && next == '*') {
            st.blockComment = true;
            blockStart = i;
            i += 2;
        } else if (c == '"') {
            qsizetype b = i;
            while (b > from && isIdent(data[b - 1]))
                --b;
            const std::string_view prefix(data + b, size_t(i - b));
            if (prefix == "R" || prefix == "u8R" || prefix == "uR" || prefix == "UR" ||
                prefix == "LR") {
                qsizetype open = i + 1;
                while (open < to && open - i <= 17 && data[open] != '(')
                    ++open;
                if (open < to && data[open] == '(') {
                    st.rawString = true;
                    st.rawDelimiter = QByteArray(data + i + 1, open - i - 1);
                    append(i, open + 1);
                    i = open + 1;
                    continue;
                }
            }
            qsizetype j = i + 1;
            while (j < to && data[j] != '"')
                j += data[j] == '\\' ? 2 : 1;
            j = std::min(j + 1, to);
            append(i, j);
            i = j;
        } else if (c == '\'') {
            qsizetype b = i;
            while (b > from && isIdent(data[b - 1]))
                --b;
            if (b < i && std::isdigit(uchar(data[b]))) { // a digit separator: 1'000
                append(i, i + 1);
                ++i;
                continue;
            }
            qsizetype j = i + 1;
            while (j < to && data[j] != '\'')
                j += data[j] == '\\' ? 2 : 1;
            j = std::min(j + 1, to);
            append(i, j);
            i = j;
        } else {
            append(i, i + 1);
            ++i;
        }
    }
    if (openComment)
        *openComment = st.blockComment ? blockStart : -1;
}

void blank(char *data, qsizetype from, qsizetype to)
{
    for (qsizetype k = from; k < to; ++k)
        if (data[k] != '\n' && data[k] != '\r')
            data[k] = ' ';
}

QByteArray identifierAt(const QByteArray &text, qsizetype *pos)
{
    qsizetype i = *pos;
    while (i < text.size() && std::isspace(uchar(text.at(i))))
        ++i;
    const qsizetype start = i;
    while (i < text.size() && isIdent(text.at(i)))
        ++i;
    *pos = i;
    return text.mid(start, i - start);
}

// One open #if ... #endif.
struct Conditional
{
    bool parentActive = true;
    bool active = true;
    bool taken = false; ///< some branch was active (or guessed)
    bool sawElse = false;
    int line = 0;
};

class Run
{
public:
    Run(QByteArray *source, const QString &file, const CppMacros &initial,
        const CppPreprocessor::IncludeLookup &lookup)
        : m_source(source), m_file(file), m_lookup(lookup)
    {
        m_result.macros = initial;
    }

    CppPreprocessor::Result run()
    {
        char *data = m_source->data();
        const qsizetype size = m_source->size();
        LexState st;
        qsizetype pos = 0;
        int line = 1;
        while (pos < size) {
            const qsizetype lineStart = pos;
            qsizetype end = m_source->indexOf('\n', pos);
            if (end < 0)
                end = size;
            qsizetype p = lineStart;
            if (!st.blockComment && !st.rawString)
                while (p < end && (data[p] == ' ' || data[p] == '\t'))
                    ++p;
            const int firstLine = line;
            if (!st.blockComment && !st.rawString && p < end && data[p] == '#') {
                // A directive: its logical line runs over backslash-continued lines.
                while (end < size) {
                    qsizetype last = end - 1;
                    if (last >= lineStart && data[last] == '\r')
                        --last;
                    if (last < lineStart || data[last] != '\\')
                        break;
                    const qsizetype more = m_source->indexOf('\n', end + 1);
                    end = more < 0 ? size : more;
                    ++line;
                }
                QByteArray text;
                qsizetype openComment = -1;
                scan(data, p + 1, end, st, &text, &openComment);
                const bool wasActive = active();
                const bool conditional = directive(text, firstLine, line);
                if (conditional || !wasActive) {
                    // A comment opened on the line and continued below stays when the code
                    // below is read, so that its end still has its start.
                    const bool keepComment = openComment >= 0 && active();
                    blank(data, lineStart, keepComment ? openComment : end);
                }
            } else {
                scan(data, lineStart, end, st, nullptr, nullptr);
                if (!active())
                    blank(data, lineStart, end);
            }
            pos = end + 1;
            ++line;
        }
        for (auto it = m_stack.crbegin(); it != m_stack.crend(); ++it)
            malformed(it->line, it->line,
                      QStringLiteral("#if at line %1 has no #endif; the file ends inside it.")
                          .arg(it->line));
        if (m_guesses > CppPreprocessor::kMaxGuessNotes) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Info;
            d.code = QStringLiteral("preprocessor-guess");
            d.evidence = Evidence::startOf(m_file);
            d.message = QStringLiteral("%1 more undecidable conditions in %2 were taken as true.")
                            .arg(m_guesses - CppPreprocessor::kMaxGuessNotes)
                            .arg(m_file);
            m_result.diagnostics.append(d);
        }
        if (!m_guard.isEmpty())
            m_result.exported.remove(m_guard);
        return m_result;
    }

private:
    bool active() const { return m_stack.empty() || m_stack.back().active; }

    // Handles one directive; true when it is a conditional one (and so is blanked).
    bool directive(const QByteArray &text, int line, int endLine)
    {
        qsizetype pos = 0;
        const QByteArray keyword = identifierAt(text, &pos);
        const QByteArray rest = text.mid(pos).trimmed();
        ++m_directives;
        if (keyword == "if" || keyword == "ifdef" || keyword == "ifndef") {
            if (m_directives == 1)
                m_guardCandidate = guardOf(keyword, rest);
            Conditional c;
            c.parentActive = active();
            c.line = line;
            m_stack.push_back(c);
            enter(keyword, rest, line, endLine);
            return true;
        }
        if (keyword == "elif" || keyword == "elifdef" || keyword == "elifndef" ||
            keyword == "else") {
            if (m_stack.empty() || m_stack.back().sawElse) {
                malformed(line, endLine,
                          m_stack.empty()
                              ? QStringLiteral("#%1 at line %2 has no #if; it is ignored.")
                                    .arg(QString::fromLatin1(keyword))
                                    .arg(line)
                              : QStringLiteral("#%1 at line %2 follows the #else of the #if at "
                                               "line %3; it is ignored.")
                                    .arg(QString::fromLatin1(keyword))
                                    .arg(line)
                                    .arg(m_stack.back().line));
                return true;
            }
            Conditional &c = m_stack.back();
            if (keyword == "else") {
                c.sawElse = true;
                c.active = c.parentActive && !c.taken;
                c.taken = true;
            } else {
                enter(keyword.mid(2), rest, line, endLine);
            }
            return true;
        }
        if (keyword == "endif") {
            if (m_stack.empty())
                malformed(line, endLine,
                          QStringLiteral("#endif at line %1 has no #if; it is ignored.").arg(line));
            else
                m_stack.pop_back();
            return true;
        }
        if (!active())
            return false;
        if (keyword == "define")
            define(rest);
        else if (keyword == "undef")
            undefine(rest);
        else if (keyword == "include")
            include(rest);
        return false;
    }

    // Decides the branch the top conditional enters: `kind` is if, ifdef or ifndef.
    void enter(const QByteArray &kind, const QByteArray &condition, int line, int endLine)
    {
        Conditional &c = m_stack.back();
        if (!c.parentActive || c.taken) {
            c.active = false;
            return;
        }
        bool value = true;
        if (int(m_stack.size()) > CppPreprocessor::kMaxDepth) {
            if (!m_reportedDepth)
                malformed(line, endLine,
                          QStringLiteral("Conditionals nest deeper than %1 levels at line %2; "
                                         "deeper ones are not evaluated, their first branch "
                                         "is kept.")
                              .arg(CppPreprocessor::kMaxDepth)
                              .arg(line));
            m_reportedDepth = true;
        } else if (kind == "ifdef" || kind == "ifndef") {
            qsizetype pos = 0;
            const QByteArray name = identifierAt(condition, &pos);
            value = m_result.macros.contains(name) == (kind == "ifdef");
        } else {
            const CppConditionEvaluator::Result r =
                CppConditionEvaluator(m_result.macros).evaluate(condition);
            value = !r.decided || r.value != 0;
            if (!r.decided)
                guess(kind, condition, line, endLine);
        }
        c.active = value;
        c.taken = value;
    }

    void guess(const QByteArray &kind, const QByteArray &condition, int line, int endLine)
    {
        if (++m_guesses > CppPreprocessor::kMaxGuessNotes)
            return;
        Diagnostic d;
        d.severity = Diagnostic::Severity::Info;
        d.code = QStringLiteral("preprocessor-guess");
        d.evidence = {m_file, line, 1, endLine, 1};
        d.message = QStringLiteral("#%1 %2 at line %3 cannot be decided without the headers it "
                                   "depends on; its branch is analysed and the branches after "
                                   "it are not.")
                        .arg(QString::fromLatin1(kind), QString::fromUtf8(condition).simplified())
                        .arg(line);
        m_result.diagnostics.append(d);
    }

    void malformed(int line, int endLine, const QString &message)
    {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.code = QStringLiteral("preprocessor-malformed");
        d.evidence = {m_file, line, 1, endLine, 1};
        d.message = QStringLiteral("%1: %2").arg(m_file, message);
        m_result.diagnostics.append(d);
    }

    void define(const QByteArray &rest)
    {
        qsizetype pos = 0;
        const QByteArray name = identifierAt(rest, &pos);
        if (name.isEmpty())
            return;
        CppMacro m;
        if (pos < rest.size() && rest.at(pos) == '(') {
            m.functionLike = true;
            const qsizetype close = rest.indexOf(')', pos);
            if (close < 0)
                return;
            for (const QByteArray &p : rest.mid(pos + 1, close - pos - 1).split(','))
                if (!p.trimmed().isEmpty())
                    m.parameters.append(p.trimmed());
            pos = close + 1;
        }
        m.body = rest.mid(pos).simplified();
        if (m_directives == 2 && name == m_guardCandidate)
            m_guard = name; // the include guard: it says nothing about the configuration
        m_result.macros.insert(name, m);
        m_result.exported.insert(name, m);
    }

    // `G` of `#ifndef G` or `#if !defined(G)`: the include guard, if a `#define G` follows.
    static QByteArray guardOf(const QByteArray &keyword, const QByteArray &condition)
    {
        QByteArray text = condition.simplified();
        if (keyword == "if") {
            text.replace(' ', "");
            if (!text.startsWith("!defined"))
                return {};
            text = text.mid(8);
            if (text.startsWith('(') && text.endsWith(')'))
                text = text.mid(1, text.size() - 2);
        }
        qsizetype pos = 0;
        const QByteArray name = identifierAt(text, &pos);
        return pos == text.size() ? name : QByteArray();
    }

    void undefine(const QByteArray &rest)
    {
        qsizetype pos = 0;
        const QByteArray name = identifierAt(rest, &pos);
        m_result.macros.remove(name);
        m_result.exported.remove(name);
    }

    void include(const QByteArray &rest)
    {
        if (!m_lookup || rest.size() < 3)
            return;
        const char open = rest.at(0);
        const char close = open == '<' ? '>' : open == '"' ? '"' : '\0';
        if (!close)
            return; // a computed include
        const qsizetype end = rest.indexOf(close, 1);
        if (end < 0)
            return;
        const CppMacros *macros = m_lookup(rest.mid(1, end - 1), open == '<');
        if (!macros)
            return;
        for (auto it = macros->cbegin(); it != macros->cend(); ++it) {
            m_result.macros.insert(it.key(), it.value());
            m_result.exported.insert(it.key(), it.value());
        }
    }

    QByteArray *m_source;
    QString m_file;
    const CppPreprocessor::IncludeLookup &m_lookup;
    CppPreprocessor::Result m_result;
    std::vector<Conditional> m_stack;
    int m_directives = 0;
    bool m_reportedDepth = false;
    int m_guesses = 0;
    QByteArray m_guardCandidate;
    QByteArray m_guard;
};

constexpr int kMaxConstantDepth = 8;

// The value of a macro body: a number, or string literals and macros standing for strings,
// concatenated ("robot/" NAME "/scan"); null for anything else.
QString constantText(const QByteArray &body, const CppMacros &macros, int depth)
{
    const QByteArray text = body.trimmed();
    if (text.isEmpty() || depth > kMaxConstantDepth)
        return {};
    if (std::isdigit(uchar(text.at(0))) || (text.at(0) == '-' && text.size() > 1)) {
        for (qsizetype i = 1; i < text.size(); ++i)
            if (!(isIdent(text.at(i)) || text.at(i) == '.' || text.at(i) == '\''))
                return {};
        return std::isdigit(uchar(text.at(text.at(0) == '-' ? 1 : 0))) ? QString::fromUtf8(text)
                                                                       : QString();
    }
    QString value;
    qsizetype i = 0;
    while (i < text.size()) {
        const char c = text.at(i);
        if (std::isspace(uchar(c))) {
            ++i;
        } else if (c == '"') {
            qsizetype j = i + 1;
            while (j < text.size() && text.at(j) != '"')
                j += text.at(j) == '\\' ? 2 : 1;
            if (j >= text.size())
                return {};
            value += QString::fromUtf8(text.mid(i + 1, j - i - 1));
            i = j + 1;
        } else if (std::isalpha(uchar(c)) || c == '_') {
            qsizetype j = i;
            while (j < text.size() && isIdent(text.at(j)))
                ++j;
            const auto it = macros.constFind(text.mid(i, j - i));
            if (it == macros.cend() || it->functionLike)
                return {};
            const QString part = constantText(it->body, macros, depth + 1);
            if (part.isNull())
                return {};
            value += part;
            i = j;
        } else {
            return {};
        }
    }
    return value.isNull() ? QStringLiteral("") : value;
}

} // namespace

CppPreprocessor::Result CppPreprocessor::run(QByteArray *source, const QString &file,
                                             const CppMacros &initial, const IncludeLookup &lookup)
{
    return Run(source, file, initial, lookup).run();
}

QString CppPreprocessor::constantValue(const QByteArray &body, const CppMacros &macros)
{
    return constantText(body, macros, 0);
}

QString CppPreprocessor::expandedValue(const CppMacro &macro, const QList<QByteArray> &arguments,
                                       const CppMacros &macros)
{
    if (!macro.functionLike || macro.parameters.size() != arguments.size() ||
        macro.body.contains("##") || macro.body.size() > 512)
        return {};
    // Parameters are replaced outside string literals only; `#x` becomes "x as written".
    const QByteArray &body = macro.body;
    QByteArray text;
    for (qsizetype i = 0; i < body.size();) {
        const char c = body.at(i);
        if (c == '"') {
            qsizetype j = i + 1;
            while (j < body.size() && body.at(j) != '"')
                j += body.at(j) == '\\' ? 2 : 1;
            text += body.mid(i, j + 1 - i);
            i = j + 1;
            continue;
        }
        const bool stringify = c == '#';
        qsizetype from = stringify ? i + 1 : i;
        while (stringify && from < body.size() && std::isspace(uchar(body.at(from))))
            ++from;
        if (from < body.size() && (std::isalpha(uchar(body.at(from))) || body.at(from) == '_')) {
            qsizetype j = from;
            while (j < body.size() && isIdent(body.at(j)))
                ++j;
            const qsizetype at = macro.parameters.indexOf(body.mid(from, j - from));
            if (at >= 0) {
                const QByteArray argument = arguments.at(at).simplified();
                if (stringify) {
                    if (argument.contains('"') || argument.contains('\\'))
                        return {};
                    text += '"' + argument + '"';
                } else {
                    text += ' ' + argument + ' ';
                }
            } else if (stringify) {
                return {};
            } else {
                text += body.mid(i, j - i);
            }
            i = j;
            continue;
        }
        if (stringify)
            return {};
        text += c;
        ++i;
    }
    return constantText(text, macros, 0);
}

} // namespace rosarch
