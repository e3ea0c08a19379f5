#include "plantuml/plantumlsyntax.h"

#include <QRegularExpression>
#include <QSet>

namespace rosarch {

namespace {

struct SourceLine
{
    QString text;
    int line = 0;
};

/// Removes `'` line comments and `/' ... '/` block comments outside quotes, keeping the line
/// breaks so line numbers stay right. A `'` only starts a comment at the start of a line or
/// after a blank, so "node's" in an arrow label survives.
QString stripComments(const QString &text)
{
    QString out;
    out.reserve(text.size());
    bool inQuote = false, inLine = false, inBlock = false;
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text.at(i);
        const QChar next = i + 1 < text.size() ? text.at(i + 1) : QChar();
        if (inBlock) {
            if (c == QLatin1Char('\'') && next == QLatin1Char('/')) {
                inBlock = false;
                ++i;
            } else if (c == QLatin1Char('\n')) {
                out += c;
            }
            continue;
        }
        if (c == QLatin1Char('\n')) {
            // A backslash-newline continues the label on the next line.
            qsizetype k = out.size() - 1;
            while (k >= 0 && (out.at(k) == QLatin1Char(' ') || out.at(k) == QLatin1Char('\t') ||
                              out.at(k) == QLatin1Char('\r')))
                --k;
            if (k < 0 || out.at(k) != QLatin1Char('\\') || inLine)
                inQuote = false;
            inLine = false;
            out += c;
            continue;
        }
        if (inLine)
            continue;
        if (c == QLatin1Char('"')) {
            inQuote = !inQuote;
        } else if (!inQuote && c == QLatin1Char('/') && next == QLatin1Char('\'')) {
            inBlock = true;
            ++i;
            continue;
        } else if (!inQuote && c == QLatin1Char('\'') && (i == 0 || text.at(i - 1).isSpace())) {
            inLine = true;
            continue;
        }
        out += c;
    }
    return out;
}

QString unescapeLabel(QString text, QStringList *stereotypes)
{
    static const QRegularExpression newline(QStringLiteral(R"(\\[nlr]|%n\(\))"));
    static const QRegularExpression stereotype(QStringLiteral(R"(<<\s*([^<>]*?)\s*>>)"));
    text.replace(newline, QStringLiteral("\n"));
    for (auto it = stereotype.globalMatch(text); it.hasNext();)
        *stereotypes << it.next().captured(1);
    text.remove(stereotype);
    text.remove(QLatin1String("**"));
    QStringList lines;
    for (const QString &l : text.split(QLatin1Char('\n')))
        if (!l.trimmed().isEmpty())
            lines << l.trimmed();
    return lines.join(QLatin1Char('\n'));
}

QString unquote(const QString &token)
{
    if (token.size() >= 2 &&
        ((token.startsWith(QLatin1Char('"')) && token.endsWith(QLatin1Char('"'))) ||
         (token.startsWith(QLatin1Char('[')) && token.endsWith(QLatin1Char(']')))))
        return token.mid(1, token.size() - 2);
    return token;
}

bool isQuoted(const QString &token)
{
    return token.startsWith(QLatin1Char('"')) || token.startsWith(QLatin1Char('['));
}

/// Splits a declaration's tail into quoted strings, [names], <<stereotypes>>, braces and words.
QStringList tokenize(const QString &s)
{
    QStringList tokens;
    qsizetype i = 0;
    const qsizetype n = s.size();
    while (i < n) {
        if (s.at(i).isSpace()) {
            ++i;
            continue;
        }
        qsizetype end = i + 1;
        const QChar c = s.at(i);
        if (c == QLatin1Char('"') || c == QLatin1Char('[')) {
            const QChar close = c == QLatin1Char('"') ? QLatin1Char('"') : QLatin1Char(']');
            end = s.indexOf(close, i + 1);
            end = end < 0 ? n : end + 1;
        } else if (s.mid(i, 2) == QLatin1String("<<")) {
            end = s.indexOf(QLatin1String(">>"), i + 2);
            end = end < 0 ? n : end + 2;
        } else if (c != QLatin1Char('{') && c != QLatin1Char('}')) {
            while (end < n && !s.at(end).isSpace() && s.at(end) != QLatin1Char('{') &&
                   s.at(end) != QLatin1Char('}') && s.mid(end, 2) != QLatin1String("<<"))
                ++end;
        }
        tokens << s.mid(i, end - i);
        i = end;
    }
    return tokens;
}

const QSet<QString> &declarationKeywords()
{
    static const QSet<QString> k = {
        QStringLiteral("component"),   QStringLiteral("portin"),  QStringLiteral("portout"),
        QStringLiteral("port"),        QStringLiteral("frame"),   QStringLiteral("folder"),
        QStringLiteral("rectangle"),   QStringLiteral("queue"),   QStringLiteral("circle"),
        QStringLiteral("interface"),   QStringLiteral("package"), QStringLiteral("namespace"),
        QStringLiteral("node"),        QStringLiteral("cloud"),   QStringLiteral("database"),
        QStringLiteral("artifact"),    QStringLiteral("card"),    QStringLiteral("file"),
        QStringLiteral("storage"),     QStringLiteral("agent"),   QStringLiteral("boundary"),
        QStringLiteral("collections"), QStringLiteral("hexagon"), QStringLiteral("stack"),
        QStringLiteral("label"),       QStringLiteral("entity"),  QStringLiteral("control"),
        QStringLiteral("actor"),       QStringLiteral("usecase"), QStringLiteral("person")};
    return k;
}

/// Statements that carry no architecture: read past without a word.
const QSet<QString> &ignoredKeywords()
{
    static const QSet<QString> k = {
        QStringLiteral("hide"),         QStringLiteral("show"),     QStringLiteral("scale"),
        QStringLiteral("left"),         QStringLiteral("top"),      QStringLiteral("allowmixing"),
        QStringLiteral("allow_mixing"), QStringLiteral("newpage"),  QStringLiteral("remove"),
        QStringLiteral("set"),          QStringLiteral("caption"),  QStringLiteral("sprite"),
        QStringLiteral("skin"),         QStringLiteral("mainframe")};
    return k;
}

/// Keywords that open a free-text section when written alone, with the words that close it.
QStringList sectionEnds(const QString &keyword)
{
    if (keyword == QLatin1String("note"))
        return {QStringLiteral("end note"), QStringLiteral("endnote")};
    if (keyword == QLatin1String("legend"))
        return {QStringLiteral("end legend"), QStringLiteral("endlegend")};
    if (keyword == QLatin1String("title"))
        return {QStringLiteral("end title"), QStringLiteral("endtitle")};
    if (keyword == QLatin1String("header"))
        return {QStringLiteral("end header"), QStringLiteral("endheader")};
    if (keyword == QLatin1String("footer"))
        return {QStringLiteral("end footer"), QStringLiteral("endfooter")};
    return {};
}

const QRegularExpression &arrowPattern()
{
    // endpoint, left head, body with optional [#color,style] and direction, right head, endpoint.
    static const QRegularExpression re(
        QStringLiteral(R"(^("[^"]*"|\[[^\]]*\]|[\w.]+)\s*)"
                       R"((<<|<\||<|\(0|0\)|[()0*#+^}]|[ox](?=[-.]))?)"
                       R"(([-.]+(?:(?:\[[^\]]*\]|(?:left|right|up|down|le|ri|do)(?![a-z]))[-.]*)*))"
                       R"((>>|\|>|>|[()0*#+^{]|[ox](?!\w))?)"
                       R"(\s*("[^"]*"|\[[^\]]*\]|[\w.]+)\s*(?::\s*(.*))?$)"));
    return re;
}

class BlockParser
{
public:
    explicit BlockParser(PlantUmlSyntax *syntax) : m_syntax(syntax) {}

    void parse(const QList<SourceLine> &physical)
    {
        const QList<SourceLine> lines = joinLines(physical);
        for (qsizetype i = 0; i < lines.size(); ++i)
            i = statement(lines, i);
    }

private:
    QList<SourceLine> joinLines(const QList<SourceLine> &in)
    {
        QList<SourceLine> out;
        for (qsizetype i = 0; i < in.size(); ++i) {
            SourceLine cur = in.at(i);
            for (int guard = 0; i + 1 < in.size() && guard < 10; ++guard) {
                const QString t = cur.text.trimmed();
                if (t.endsWith(QLatin1Char('\\'))) {
                    const bool inLabel = t.count(QLatin1Char('"')) % 2 == 1;
                    cur.text = t.chopped(1) +
                               (inLabel ? QStringLiteral("\\n") : QStringLiteral(" ")) +
                               in.at(++i).text.trimmed();
                    m_syntax->notes
                        << QStringLiteral("line %1: backslash-newline joined with line %2")
                               .arg(cur.line)
                               .arg(in.at(i).line);
                } else if (t.count(QLatin1Char('"')) % 2 == 1) {
                    cur.text = t + QStringLiteral("\\n") + in.at(++i).text.trimmed();
                    m_syntax->notes << QStringLiteral("line %1: quoted label continued on line %2")
                                           .arg(cur.line)
                                           .arg(in.at(i).line);
                } else {
                    break;
                }
            }
            out << cur;
        }
        return out;
    }

    int openParent() const
    {
        for (qsizetype k = m_stack.size() - 1; k >= 0; --k)
            if (m_stack.at(k) >= 0)
                return m_stack.at(k);
        return -1;
    }

    void warn(const SourceLine &l)
    {
        m_syntax->warnings
            << QStringLiteral("line %1: cannot read '%2'").arg(l.line).arg(l.text.trimmed());
    }

    qsizetype statement(const QList<SourceLine> &lines, qsizetype i)
    {
        const SourceLine &l = lines.at(i);
        const QString t = l.text.trimmed();
        if (t.isEmpty())
            return i;
        if (t.startsWith(QLatin1Char('!')) || t.startsWith(QLatin1Char('@')))
            return i; // !theme, !include, !define; @startuml inside a block
        const QString keyword =
            t.section(QRegularExpression(QStringLiteral(R"([\s{:]+)")), 0, 0).toLower();
        if (t == QLatin1String("{")) {
            if (!m_syntax->declarations.isEmpty() && !m_syntax->declarations.last().hasBlock) {
                m_syntax->declarations.last().hasBlock = true;
                m_stack << int(m_syntax->declarations.size() - 1);
            } else {
                m_stack << -1;
            }
            return i;
        }
        if (QRegularExpression(QStringLiteral(R"(^\}+$)")).match(t).hasMatch()) {
            for (qsizetype k = 0; k < t.size() && !m_stack.isEmpty(); ++k)
                m_stack.removeLast();
            return i;
        }
        if (keyword == QLatin1String("skinparam")) {
            if (!t.endsWith(QLatin1Char('{')))
                return i;
            int depth = 1;
            while (depth > 0 && i + 1 < lines.size()) {
                const QString s = lines.at(++i).text;
                depth += int(s.count(QLatin1Char('{'))) - int(s.count(QLatin1Char('}')));
            }
            return i;
        }
        const QStringList ends = sectionEnds(keyword);
        if (!ends.isEmpty()) {
            const QString rest = t.mid(keyword.size()).trimmed();
            const bool oneLine =
                keyword == QLatin1String("note")
                    ? rest.contains(QLatin1Char(':')) || rest.startsWith(QLatin1Char('"'))
                    : keyword != QLatin1String("legend") && !rest.isEmpty();
            if (keyword == QLatin1String("title") && !rest.isEmpty())
                m_syntax->title =
                    unquote(rest.startsWith(QLatin1Char(':')) ? rest.mid(1).trimmed() : rest);
            if (oneLine)
                return i;
            while (i + 1 < lines.size()) {
                const QString s = lines.at(++i).text.trimmed().toLower();
                if (ends.contains(s.simplified()))
                    break;
            }
            return i;
        }
        if (ignoredKeywords().contains(keyword))
            return i;
        // Arrows first: the ACD's alias `node` is also a keyword (`node --0 srv_ps1`).
        const QRegularExpressionMatch arrow = arrowPattern().match(t);
        if (arrow.hasMatch()) {
            addArrow(l, arrow);
            return i;
        }
        static const QRegularExpression named(QStringLiteral(R"(^\s*("|\[|[\w.]))"));
        if (declarationKeywords().contains(keyword) &&
            named.match(t.mid(keyword.size())).hasMatch())
            declaration(l, keyword, t.mid(keyword.size()));
        else if (t.startsWith(QLatin1Char('[')))
            declaration(l, QStringLiteral("component"), t);
        else
            warn(l);
        return i;
    }

    void declaration(const SourceLine &l, const QString &keyword, const QString &tail)
    {
        const QStringList tokens = tokenize(tail);
        PlantUmlDeclaration d;
        d.keyword = keyword;
        d.line = l.line;
        d.parent = openParent();
        QString name, asName;
        bool nameQuoted = false, asQuoted = false, opens = false, closes = false;
        for (qsizetype k = 0; k < tokens.size(); ++k) {
            const QString &tok = tokens.at(k);
            if (tok.startsWith(QLatin1String("<<")))
                d.stereotypes << tok.mid(2, tok.size() - 4).trimmed();
            else if (tok == QLatin1String("{"))
                opens = true;
            else if (tok == QLatin1String("}"))
                closes = opens;
            else if (opens)
                continue; // `{ ... }` on one line: the inside is not read
            else if (tok.compare(QLatin1String("as"), Qt::CaseInsensitive) == 0 &&
                     k + 1 < tokens.size()) {
                asName = tokens.at(++k);
                asQuoted = isQuoted(asName);
            } else if (tok.startsWith(QLatin1Char('#'))) {
                continue; // a fill colour
            } else if (name.isEmpty()) {
                name = tok;
                nameQuoted = isQuoted(tok);
            }
        }
        QString label = unquote(name);
        if (asName.isEmpty()) {
            d.alias = label;
        } else if (!nameQuoted && asQuoted) { // component alias as "label"
            d.alias = name;
            label = unquote(asName);
        } else {
            d.alias = unquote(asName);
        }
        d.label = unescapeLabel(label, &d.stereotypes);
        d.hasBlock = opens && !closes;
        m_syntax->declarations << d;
        if (d.hasBlock)
            m_stack << int(m_syntax->declarations.size() - 1);
    }

    void addArrow(const SourceLine &l, const QRegularExpressionMatch &m)
    {
        PlantUmlArrow a;
        a.line = l.line;
        a.from = unquote(m.captured(1));
        a.to = unquote(m.captured(5));
        const QString left = m.captured(2), right = m.captured(4), body = m.captured(3);
        static const QRegularExpression color(QStringLiteral(R"(#([A-Za-z0-9]+))"));
        const QRegularExpressionMatch c = color.match(body);
        if (c.hasMatch())
            a.color = c.captured(1).toLower();
        QStringList ignored;
        a.label = unescapeLabel(unquote(m.captured(6).trimmed()), &ignored);
        const bool pointsLeft = left.contains(QLatin1Char('<')),
                   pointsRight = right.contains(QLatin1Char('>'));
        a.directed = pointsLeft != pointsRight;
        if (pointsLeft && !pointsRight)
            std::swap(a.from, a.to);
        for (const QString &head : {right, left})
            if (head == QLatin1String("0") || head == QLatin1String("("))
                a.head = head;
        m_syntax->arrows << a;
    }

    PlantUmlSyntax *m_syntax;
    QList<int> m_stack; ///< open blocks: declaration index, or -1 for an anonymous `{`
};

} // namespace

QList<PlantUmlSyntax> PlantUmlSyntax::parse(const QString &text)
{
    QString clean = stripComments(text);
    clean.remove(QLatin1Char('\r'));
    const QStringList lines = clean.split(QLatin1Char('\n'));
    QList<QList<SourceLine>> blocks;
    bool sawStart = false, inside = false;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString t = lines.at(i).trimmed();
        if (t.startsWith(QLatin1String("@startuml"), Qt::CaseInsensitive)) {
            sawStart = inside = true;
            blocks.append(QList<SourceLine>());
            continue;
        }
        if (t.startsWith(QLatin1String("@enduml"), Qt::CaseInsensitive)) {
            inside = false;
            continue;
        }
        if (inside)
            blocks.last().append(SourceLine{lines.at(i), int(i + 1)});
    }
    if (!sawStart) {
        blocks.append(QList<SourceLine>());
        for (qsizetype i = 0; i < lines.size(); ++i)
            blocks.last().append(SourceLine{lines.at(i), int(i + 1)});
    }
    QList<PlantUmlSyntax> out;
    for (const QList<SourceLine> &block : std::as_const(blocks)) {
        PlantUmlSyntax s;
        if (!sawStart)
            s.notes << QStringLiteral("line 1: no @startuml; read the whole text as one diagram");
        BlockParser(&s).parse(block);
        out << s;
    }
    return out;
}

int PlantUmlSyntax::find(const QString &name) const
{
    for (qsizetype i = 0; i < declarations.size(); ++i)
        if (declarations.at(i).alias == name)
            return int(i);
    for (qsizetype i = 0; i < declarations.size(); ++i)
        if (declarations.at(i).label == name)
            return int(i);
    return -1;
}

} // namespace rosarch
