#include "launch/xmlyaml/frontendsubstitution.h"

namespace rosarch {

namespace {

using Kind = Substitution::Kind;

// Deeper nesting is never written by hand; the limit keeps hostile input from exhausting the stack.
constexpr int kMaxDepth = 64;

Substitution joined(QList<Substitution> parts)
{
    if (parts.isEmpty())
        return Substitution::literal(QString());
    return Substitution::concat(std::move(parts));
}

/// Collects the fragments of a template, merging adjacent literal text.
class Fragments
{
public:
    void addText(QChar c) { m_text += c; }
    void add(const Substitution &s)
    {
        if (s.kind == Kind::Text) {
            m_text += s.text;
            return;
        }
        flush();
        m_parts << s;
    }
    void addAll(const QList<Substitution> &parts)
    {
        for (const Substitution &s : parts)
            add(s);
    }
    QList<Substitution> take()
    {
        flush();
        return std::move(m_parts);
    }

private:
    void flush()
    {
        if (!m_text.isEmpty())
            m_parts << Substitution::literal(m_text);
        m_text.clear();
    }

    QString m_text;
    QList<Substitution> m_parts;
};

/// Recursive descent over the grammar of launch/frontend/grammar.lark, a little more lenient:
/// quotes may appear inside an argument, runs of spaces separate arguments, and parentheses
/// balance inside an unquoted argument. A backslash escapes the next character (as
/// `replace_escaped_characters` does in launch).
class Parser
{
public:
    explicit Parser(const QString &s) : m_s(s), m_n(int(s.size())) {}

    bool failed() const { return !m_error.isEmpty(); }
    QString error() const { return m_error; }

    QList<Substitution> parseTemplate()
    {
        Fragments f;
        while (m_pos < m_n && !failed()) {
            const QChar c = m_s[m_pos];
            if (c == u'\\' && m_pos + 1 < m_n) {
                f.addText(m_s[m_pos + 1]);
                m_pos += 2;
            } else if (startsSubstitution()) {
                f.add(parseSubstitution(QChar(), 0));
            } else {
                f.addText(c);
                ++m_pos;
            }
        }
        return f.take();
    }

private:
    bool startsSubstitution() const
    {
        return m_s[m_pos] == u'$' && m_pos + 1 < m_n && m_s[m_pos + 1] == u'(';
    }

    void fail(int offset, const QString &message)
    {
        if (!failed())
            m_error = QStringLiteral("%1 at column %2").arg(message).arg(offset + 1);
    }

    Substitution parseSubstitution(QChar quote, int depth)
    {
        const int start = m_pos;
        if (depth > kMaxDepth) {
            fail(start, QStringLiteral("substitutions nested too deeply"));
            return {};
        }
        m_pos += 2;
        const int nameStart = m_pos;
        if (m_pos < m_n && m_s[m_pos].isLetter()) {
            ++m_pos;
            while (m_pos < m_n &&
                   (m_s[m_pos].isLetterOrNumber() || m_s[m_pos] == u'_' || m_s[m_pos] == u'-'))
                ++m_pos;
        }
        const QString name = m_s.mid(nameStart, m_pos - nameStart);
        if (name.isEmpty()) {
            fail(start, QStringLiteral("a substitution name is expected after '$('"));
            return {};
        }
        QList<QList<Substitution>> args;
        bool separated = false;
        while (!failed()) {
            if (m_pos >= m_n) {
                fail(start,
                     QStringLiteral("unbalanced parentheses: '$(%1' is not closed").arg(name));
                return {};
            }
            const QChar c = m_s[m_pos];
            if (c == u')') {
                ++m_pos;
                return make(name, args, m_s.mid(start, m_pos - start));
            }
            if (c.isSpace()) {
                ++m_pos;
                separated = true;
                continue;
            }
            if (!separated) {
                fail(m_pos,
                     QStringLiteral("unbalanced parentheses: '$(%1' is not closed").arg(name));
                return {};
            }
            args << parseValue(quote, depth);
            separated = false;
        }
        return {};
    }

    QList<Substitution> parseValue(QChar quote, int depth)
    {
        Fragments f;
        int parens = 0;
        while (m_pos < m_n && !failed()) {
            const QChar c = m_s[m_pos];
            if (c == u'\\' && m_pos + 1 < m_n) {
                f.addText(m_s[m_pos + 1]);
                m_pos += 2;
                continue;
            }
            if (startsSubstitution()) {
                f.add(parseSubstitution(quote, depth + 1));
                continue;
            }
            if (c.isSpace())
                break;
            if (c == u')') {
                if (parens == 0)
                    break;
                --parens;
            } else if (c == u'(') {
                ++parens;
            } else if (quote.isNull() && (c == u'\'' || c == u'"')) {
                f.addAll(parseQuoted(c, depth));
                continue;
            } else if (!quote.isNull() && c == quote) {
                break; // the enclosing quoted template ends inside a substitution
            }
            f.addText(c);
            ++m_pos;
        }
        return f.take();
    }

    QList<Substitution> parseQuoted(QChar quote, int depth)
    {
        const int start = m_pos;
        ++m_pos;
        Fragments f;
        while (!failed()) {
            if (m_pos >= m_n) {
                fail(start, QStringLiteral("unterminated quote %1").arg(quote));
                return {};
            }
            const QChar c = m_s[m_pos];
            if (c == u'\\' && m_pos + 1 < m_n) {
                f.addText(m_s[m_pos + 1]);
                m_pos += 2;
            } else if (c == quote) {
                ++m_pos;
                break;
            } else if (startsSubstitution()) {
                f.add(parseSubstitution(quote, depth + 1));
            } else {
                f.addText(c);
                ++m_pos;
            }
        }
        return f.take();
    }

    static Substitution make(const QString &name, const QList<QList<Substitution>> &args,
                             const QString &raw)
    {
        QList<Substitution> values;
        for (const auto &a : args)
            values << joined(a);
        const auto count = values.size();
        Substitution s;
        if (name == u"var" && (count == 1 || count == 2) && values[0].isLiteral()) {
            s = Substitution::configuration(values[0].text);
            if (count == 2)
                s.parts << values[1];
            return s;
        }
        if ((name == u"env" || name == u"optenv") && (count == 1 || count == 2) &&
            values[0].isLiteral()) {
            s.kind = Kind::EnvironmentVariable;
            s.text = values[0].text;
            if (count == 2)
                s.parts << values[1];
            else if (name == u"optenv")
                s.parts << Substitution::literal(QString());
            return s;
        }
        if ((name == u"find-pkg-share" || name == u"find-pkg-prefix") && count == 1) {
            s.kind = name == u"find-pkg-share" ? Kind::FindPackageShare : Kind::FindPackagePrefix;
            s.parts << values[0];
            return s;
        }
        if (name == u"dirname" && count == 0) {
            s.kind = Kind::ThisLaunchFileDir;
            return s;
        }
        if (name == u"filename" && count == 0) {
            s.kind = Kind::ThisLaunchFile;
            return s;
        }
        if (name == u"eval" && count >= 1) {
            s.kind = Kind::Eval;
            if (count <= 2) { // a second argument names Python modules to import
                s.parts = args[0];
                return s;
            }
            Fragments f; // an unquoted expression: its words were split into arguments
            for (int i = 0; i < count; ++i) {
                if (i > 0)
                    f.add(Substitution::literal(QStringLiteral(" ")));
                f.addAll(args[i]);
            }
            s.parts = f.take();
            return s;
        }
        const bool binary =
            name == u"equals" || name == u"not-equals" || name == u"and" || name == u"or";
        if ((binary && count == 2) || (name == u"not" && count == 1) ||
            (name == u"if" && (count == 2 || count == 3)) || name == u"all" || name == u"any")
            return Substitution::function(name, values);
        // command, anon, param, file-content, ...: kept as written, with the
        // parsed arguments for whoever wants to look inside.
        s = Substitution::unknown(raw);
        s.parts = values;
        return s;
    }

    const QString &m_s;
    const int m_n;
    int m_pos = 0;
    QString m_error;
};

} // namespace

Substitution FrontendSubstitution::parse(const QString &value, QString *error)
{
    if (error)
        error->clear();
    Parser parser(value);
    QList<Substitution> parts = parser.parseTemplate();
    if (parser.failed()) {
        if (error)
            *error = parser.error();
        return Substitution::unknown(value);
    }
    return joined(std::move(parts));
}

} // namespace rosarch
