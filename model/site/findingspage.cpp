#include "site/findingspage.h"
#include "core/diagnostickind.h"

#include <QCoreApplication>
#include <QMap>
#include <QSet>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::FindingsPage", text);
}

using SiteHtml::code;
using SiteHtml::escape;

QString select(const QString &id, const QString &label, const QString &all,
               const QStringList &values)
{
    QString out = QStringLiteral("<label for=\"%1\">%2</label><select id=\"%1\" data-filter=\"%1\">"
                                 "<option value=\"\">%3</option>")
                      .arg(id, escape(label), escape(all));
    for (const QString &v : values)
        out += QStringLiteral("<option>%1</option>").arg(escape(v));
    return out + QStringLiteral("</select>\n");
}

QString kindAnchor(const QString &code)
{
    QString id = QStringLiteral("kind-");
    for (const QChar c : code)
        id += c.isLetterOrNumber() && c.unicode() < 128 ? c : QChar(u'-');
    return id;
}

} // namespace

SiteFile FindingsPage::write(const SiteContext &context)
{
    const SiteModel &model = *context.model;
    const QString path = QStringLiteral("findings.html");
    QMap<QString, int> codes;
    QSet<QString> packages;
    QSet<QString> systems;
    QList<QStringList> rows;
    QStringList rowAttributes;
    int accepted = 0;
    int hidden = 0;
    for (const Diagnostic &d : model.findings()) {
        codes[d.code] += 1;
        const QString package = model.packageOf(d.evidence.file);
        if (!package.isEmpty())
            packages.insert(package);
        for (const QString &s : d.contexts)
            systems.insert(s);
        QString mark;
        QString state;
        if (const FindingMark *m = model.project().finding(d.key())) {
            const bool isAccepted = m->status == FindingMark::Status::Accepted;
            (isAccepted ? accepted : hidden) += 1;
            state = isAccepted ? QStringLiteral("accepted") : QStringLiteral("hidden");
            mark = QStringLiteral(" <span class=\"tag\">%1</span>")
                       .arg(escape(isAccepted ? tr("accepted") : tr("hidden")));
            if (!m->reason.isEmpty())
                mark += QStringLiteral(" <span class=\"muted\">%1</span>").arg(escape(m->reason));
        }
        QString message = escape(d.message) + mark;
        if (!d.related.isEmpty()) {
            message += QStringLiteral("<ul class=\"related\">");
            for (const Diagnostic::Related &r : d.related)
                message += QStringLiteral("<li>%1 %2</li>")
                               .arg(escape(r.message), SiteHtml::source(context, path, r.evidence));
            message += QStringLiteral("</ul>");
        }
        const QString severity = Diagnostic::severityName(d.severity);
        rows << QStringList{
            QStringLiteral("<span class=\"sev %1\">%1</span>").arg(escape(severity)),
            QStringLiteral("<a href=\"#%1\">%2</a>").arg(kindAnchor(d.code), escape(d.code)),
            message, SiteHtml::source(context, path, d.evidence),
            escape(d.contexts.join(QStringLiteral(", ")))};
        rowAttributes << QStringLiteral(
                             " data-severity=\"%1\" data-code=\"%2\" data-package=\"%3\" "
                             "data-systems=\"%4\"%5")
                             .arg(escape(severity), escape(d.code), escape(package),
                                  escape(d.contexts.join(u'\n')),
                                  state.isEmpty() ? QString()
                                                  : QStringLiteral(" data-mark=\"%1\"").arg(state));
    }
    QString body = QStringLiteral("<p class=\"lead\">%1</p>\n")
                       .arg(escape(tr("%1 findings of the analysis and the architecture checks; "
                                      "%2 accepted and %3 hidden in the project.")
                                       .arg(rows.size())
                                       .arg(accepted)
                                       .arg(hidden)));
    QStringList packageList = packages.values();
    std::sort(packageList.begin(), packageList.end());
    QStringList systemList = systems.values();
    std::sort(systemList.begin(), systemList.end());
    body += QStringLiteral("<form class=\"filters\" aria-label=\"%1\">\n")
                .arg(escape(tr("Filter findings")));
    body += select(QStringLiteral("severity"), tr("Severity"), tr("any"),
                   {QStringLiteral("error"), QStringLiteral("warning"), QStringLiteral("info")});
    body += select(QStringLiteral("code"), tr("Kind"), tr("any"), codes.keys());
    body += select(QStringLiteral("package"), tr("Package"), tr("any"), packageList);
    body += select(QStringLiteral("system"), tr("System"), tr("any"), systemList);
    body += QStringLiteral("<label><input type=\"checkbox\" id=\"show-hidden\"> %1</label>\n"
                           "<output id=\"finding-count\" for=\"severity code package "
                           "system\"></output>\n</form>\n")
                .arg(escape(tr("show hidden")));

    // The table with a data attribute per row: SiteHtml::table has none, so it is written here.
    body += QStringLiteral(
                "<div class=\"scroll\"><table id=\"findings\"><caption>%1</caption>\n<thead><tr>")
                .arg(escape(tr("Findings")));
    for (const QString &h : {tr("Severity"), tr("Kind"), tr("Finding"), tr("Where"), tr("Systems")})
        body += QStringLiteral("<th scope=\"col\">%1</th>").arg(escape(h));
    body += QStringLiteral("</tr></thead>\n<tbody>\n");
    for (qsizetype i = 0; i < rows.size(); ++i) {
        body += QStringLiteral("<tr%1>").arg(rowAttributes[i]);
        for (const QString &cell : rows[i])
            body += QStringLiteral("<td>%1</td>").arg(cell);
        body += QStringLiteral("</tr>\n");
    }
    body += QStringLiteral("</tbody></table></div>\n");

    body += QStringLiteral("<section aria-labelledby=\"kinds\">\n<h2 id=\"kinds\">%1</h2>\n")
                .arg(escape(tr("Kinds of finding")));
    for (auto it = codes.cbegin(); it != codes.cend(); ++it) {
        const DiagnosticKind kind = DiagnosticKind::of(it.key());
        body += QStringLiteral("<section id=\"%1\" class=\"kind\">\n<h3>%2 <span "
                               "class=\"muted\">%3 · %4</span></h3>\n"
                               "<p>%5</p>\n</section>\n")
                    .arg(kindAnchor(it.key()), escape(kind.title), code(it.key()))
                    .arg(it.value())
                    .arg(escape(kind.help));
    }
    body += QStringLiteral("</section>\n");
    return SiteHtml::page(context, path, tr("Findings"),
                          {{tr("Home"), QStringLiteral("index.html")}, {tr("Findings"), path}},
                          body);
}

} // namespace rosarch
