#include "site/sitehtml.h"

#include <QCoreApplication>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::SiteHtml", text);
}

int depthOf(const QString &path)
{
    return int(path.count(u'/'));
}

} // namespace

QString SiteHtml::escape(const QString &text)
{
    QString out;
    out.reserve(text.size() + text.size() / 8);
    for (const QChar c : text) {
        switch (c.unicode()) {
        case '&':
            out += QLatin1String("&amp;");
            break;
        case '<':
            out += QLatin1String("&lt;");
            break;
        case '>':
            out += QLatin1String("&gt;");
            break;
        case '"':
            out += QLatin1String("&quot;");
            break;
        case '\'':
            out += QLatin1String("&#39;");
            break;
        default:
            // Control characters from files are not text a page can show.
            out += c.unicode() < 0x20 && c != u'\n' && c != u'\t' ? QChar(u' ') : c;
        }
    }
    return out;
}

QString SiteHtml::href(const QString &from, const QString &to)
{
    const qsizetype hash = to.indexOf(u'#');
    if (hash == 0)
        return to;
    // Every page is at most one folder deep.
    const QString file = hash < 0 ? to : to.left(hash);
    const QString fragment = hash < 0 ? QString() : to.mid(hash);
    const QString fromDir = from.section(u'/', 0, -2);
    const QString toDir = file.section(u'/', 0, -2);
    if (fromDir == toDir)
        return file.section(u'/', -1) + fragment;
    return QStringLiteral("../").repeated(depthOf(from)) + file + fragment;
}

QString SiteHtml::link(const QString &from, const QString &to, const QString &text)
{
    if (to.isEmpty())
        return escape(text);
    return QStringLiteral("<a href=\"%1\">%2</a>").arg(escape(href(from, to)), escape(text));
}

QString SiteHtml::source(const SiteContext &context, const QString &from, const Evidence &evidence)
{
    const QString url = context.source.url(evidence, depthOf(from));
    if (url.isEmpty())
        return {};
    const QString text = evidence.line > 0
                             ? QStringLiteral("%1:%2").arg(evidence.file).arg(evidence.line)
                             : evidence.file;
    return QStringLiteral("<a class=\"src\" href=\"%1\">%2</a>").arg(escape(url), escape(text));
}

QString SiteHtml::code(const QString &text)
{
    return QStringLiteral("<code>%1</code>").arg(escape(text));
}

QString SiteHtml::table(const QString &caption, const QStringList &headers,
                        const QList<QStringList> &rows, const QString &cssClass)
{
    QString out = cssClass.isEmpty()
                      ? QStringLiteral("<div class=\"scroll\"><table>")
                      : QStringLiteral("<div class=\"scroll\"><table class=\"%1\">").arg(cssClass);
    out += QStringLiteral("<caption>%1</caption>\n<thead><tr>").arg(escape(caption));
    for (const QString &h : headers)
        out += QStringLiteral("<th scope=\"col\">%1</th>").arg(escape(h));
    out += QStringLiteral("</tr></thead>\n<tbody>\n");
    for (const QStringList &row : rows) {
        out += QStringLiteral("<tr>");
        for (const QString &cell : row)
            out += QStringLiteral("<td>%1</td>").arg(cell);
        out += QStringLiteral("</tr>\n");
    }
    return out + QStringLiteral("</tbody></table></div>\n");
}

SiteFile SiteHtml::page(const SiteContext &context, const QString &path, const QString &title,
                        const QList<QPair<QString, QString>> &crumbs, const QString &body)
{
    const QString root = QStringLiteral("../").repeated(depthOf(path));
    QString out = QStringLiteral("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n"
                                 "<meta charset=\"utf-8\">\n"
                                 "<meta name=\"viewport\" content=\"width=device-width, "
                                 "initial-scale=1\">\n"
                                 "<meta name=\"color-scheme\" content=\"light dark\">\n");
    out += QStringLiteral("<title>%1</title>\n")
               .arg(escape(path == QLatin1String("index.html")
                               ? context.title
                               : QStringLiteral("%1 · %2").arg(title, context.title)));
    out += QStringLiteral("<link rel=\"stylesheet\" href=\"%1assets/site.css\">\n"
                          "<script src=\"%1assets/search-index.js\" defer></script>\n"
                          "<script src=\"%1assets/site.js\" defer></script>\n"
                          "</head>\n<body data-root=\"%1\">\n")
               .arg(root);
    out += QStringLiteral("<a class=\"skip\" href=\"#main\">%1</a>\n").arg(tr("Skip to content"));
    out +=
        QStringLiteral("<header class=\"top\">\n<a class=\"brand\" href=\"%1index.html\">%2</a>\n")
            .arg(root, escape(context.title));
    out += QStringLiteral("<nav aria-label=\"%1\"><ul>"
                          "<li><a href=\"%2index.html#systems\">%3</a></li>"
                          "<li><a href=\"%2index.html#packages\">%4</a></li>"
                          "<li><a href=\"%2findings.html\">%5</a></li></ul></nav>\n")
               .arg(tr("Site"), root, tr("Systems"), tr("Packages"), tr("Findings"));
    out +=
        QStringLiteral("<form class=\"search\" role=\"search\" action=\"%1search.html\">"
                       "<label for=\"search-box\">%2</label>"
                       "<input id=\"search-box\" name=\"q\" type=\"search\" autocomplete=\"off\" "
                       "placeholder=\"%3\" aria-controls=\"search-results\">"
                       "<ul id=\"search-results\" class=\"results\" hidden></ul></form>\n"
                       "</header>\n")
            .arg(root, tr("Search"), tr("node, topic, launch file…"));
    out += QStringLiteral("<main id=\"main\">\n");
    if (crumbs.size() > 1) {
        out += QStringLiteral("<nav class=\"crumbs\" aria-label=\"%1\"><ol>").arg(tr("Breadcrumb"));
        for (qsizetype i = 0; i < crumbs.size(); ++i)
            out += i + 1 == crumbs.size() ? QStringLiteral("<li aria-current=\"page\">%1</li>")
                                                .arg(escape(crumbs[i].first))
                                          : QStringLiteral("<li>%1</li>")
                                                .arg(link(path, crumbs[i].second, crumbs[i].first));
        out += QStringLiteral("</ol></nav>\n");
    }
    out += QStringLiteral("<h1>%1</h1>\n").arg(escape(title));
    out += body;
    out += QStringLiteral("</main>\n<footer>%1</footer>\n</body>\n</html>\n")
               .arg(escape(tr("Written by rosarch %1 from the model it recovered from the "
                              "source; nothing here was run.")
                               .arg(context.version)));
    return {path, out.toUtf8()};
}

} // namespace rosarch
