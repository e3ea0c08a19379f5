#include "suggestions/nodedocumentation.h"

#include <QRegularExpression>

namespace rosarch {

namespace {

/// The first paragraph of a doc text as one line, shortened to its first sentence when long.
QString summary(const QStringList &text)
{
    QStringList paragraph;
    for (const QString &l : text) {
        if (l.trimmed().isEmpty()) {
            if (!paragraph.isEmpty())
                break;
            continue;
        }
        paragraph << l.trimmed();
    }
    QString s = paragraph.join(QLatin1Char(' ')).simplified();
    if (s.size() > 200) {
        const qsizetype dot = s.indexOf(QLatin1String(". "));
        s = dot > 0 && dot < 200 ? s.left(dot + 1) : s.left(197) + QStringLiteral("...");
    }
    return s;
}

bool looksLikeLicense(const QStringList &text)
{
    const QString all = text.join(QLatin1Char(' '));
    return all.contains(QLatin1String("Copyright")) || all.contains(QLatin1String("License")) ||
           all.contains(QLatin1String("SPDX"));
}

/// A Python string literal (docstring) starting on line `at` (0-based).
bool pythonDocstring(const QStringList &lines, int at, QStringList *text, int *last)
{
    if (at < 0 || at >= lines.size())
        return false;
    QString t = lines[at].trimmed();
    if (t.size() > 1 && QStringLiteral("rRuUbB").contains(t.at(0)) &&
        (t.at(1) == QLatin1Char('"') || t.at(1) == QLatin1Char('\'')))
        t = t.mid(1);
    for (const QString &delim : {QStringLiteral("\"\"\""), QStringLiteral("'''"),
                                 QStringLiteral("\""), QStringLiteral("'")}) {
        if (!t.startsWith(delim))
            continue;
        QString rest = t.mid(delim.size());
        const qsizetype close = rest.indexOf(delim);
        if (close >= 0) {
            *text = {rest.left(close)};
            *last = at;
            return true;
        }
        if (delim.size() == 1)
            return false;
        *text = {rest};
        for (int i = at + 1; i < lines.size(); ++i) {
            const qsizetype end = lines[i].indexOf(delim);
            if (end >= 0) {
                text->append(lines[i].left(end));
                *last = i;
                return true;
            }
            text->append(lines[i]);
        }
        return false;
    }
    return false;
}

/// The comment block (C++ // /// /* */ or Python #) that ends right above line `above` (0-based).
bool commentAbove(const QStringList &lines, int above, bool python, QStringList *text, int *first,
                  int *last)
{
    int i = above - 1;
    while (i >= 0 && lines[i].trimmed().startsWith(QLatin1String("template")))
        --i; // a template header sits between the comment and the class
    const int end = i;
    auto isComment = [&](const QString &t) {
        return python ? t.startsWith(QLatin1Char('#'))
                      : t.startsWith(QLatin1String("//")) || t.startsWith(QLatin1String("/*")) ||
                            t.startsWith(QLatin1Char('*')) || t.endsWith(QLatin1String("*/"));
    };
    while (i >= 0 && isComment(lines[i].trimmed()))
        --i;
    if (i == end)
        return false;
    static const QRegularExpression markers(
        QStringLiteral("^(#+!?|///?<?|//!|/\\*\\*?!?|\\*+/?)\\s*"));
    // Doxygen's words for what the text is about, not what it says (`@brief` and `@details`
    // introduce the text itself): their lines are left out, and the description ends at the
    // first parameter or return value.
    static const QRegularExpression lead(QStringLiteral("^[@\\\\](brief|details)\\s+"));
    static const QRegularExpression structural(QStringLiteral(
        "^[@\\\\](class|struct|file|namespace|fn|author|date|version|copyright|ingroup|"
        "defgroup|addtogroup|sa|see|note)\\b"));
    static const QRegularExpression ends(
        QStringLiteral("^[@\\\\](param|tparam|return|returns|retval|throws|exception)\\b"));
    // a banner: a line of nothing but rule characters (`*****`, `=====`, `-----`)
    static const QRegularExpression banner(QStringLiteral("^[-*=#/~_+\\s]*$"));
    text->clear();
    for (int l = i + 1; l <= end; ++l) {
        QString t = lines[l].trimmed();
        if (t.endsWith(QLatin1String("*/")))
            t.chop(2);
        t.remove(markers);
        t = t.trimmed();
        if (ends.match(t).hasMatch())
            break;
        if (structural.match(t).hasMatch() || (!t.isEmpty() && banner.match(t).hasMatch()))
            continue;
        t.remove(lead);
        text->append(t.trimmed());
    }
    *first = i + 1;
    *last = end;
    return true;
}

QString firstContentLine(const QStringList &text)
{
    for (const QString &l : text)
        if (!l.trimmed().isEmpty())
            return l.trimmed();
    return {};
}

} // namespace

std::optional<NodeDocumentation> NodeDocumentation::read(const SuggestionSource &source,
                                                         const AtomicNode &node)
{
    const QStringList lines = source.lines(node.evidence.file);
    const int start = node.evidence.line - 1;
    if (lines.isEmpty() || start < 0 || start >= lines.size())
        return std::nullopt;
    const bool python = node.compileType == AtomicNode::CompileType::Python;
    QStringList doc;
    int from = 0;
    int to = 0;
    bool found = false;
    if (python && !node.procedural) {
        int header = start;
        while (header < lines.size() &&
               !lines[header].section(QLatin1Char('#'), 0, 0).trimmed().endsWith(QLatin1Char(':')))
            ++header;
        int body = header + 1;
        while (body < lines.size() && lines[body].trimmed().isEmpty())
            ++body;
        found = pythonDocstring(lines, body, &doc, &to);
        from = body;
    }
    if (!found)
        found = commentAbove(lines, start, python, &doc, &from, &to) && !looksLikeLicense(doc);
    if (!found && python) {
        // A procedural node (or an undocumented class) is described by its module docstring.
        int top = 0;
        while (top < lines.size() && (lines[top].trimmed().isEmpty() ||
                                      lines[top].trimmed().startsWith(QLatin1Char('#'))))
            ++top;
        found = pythonDocstring(lines, top, &doc, &to);
        from = top;
    }
    if (!found)
        return std::nullopt;
    NodeDocumentation d{summary(doc), firstContentLine(doc), from + 1, to + 1};
    if (d.text.isEmpty() || d.quote.isEmpty())
        return std::nullopt;
    return d;
}

} // namespace rosarch
