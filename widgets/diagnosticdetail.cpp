#include "widgets/diagnosticdetail.h"
#include "core/diagnostickind.h"
#include "core/visibletext.h"
#include "widgets/diagnosticmodel.h"

#include <QLocale>
#include <QUrl>

namespace rosarch {

namespace {

QString link(int index, const Evidence &e)
{
    const QString where = e.line > 0 ? QStringLiteral("%1:%2").arg(e.file).arg(e.line) : e.file;
    if (!e.isValid())
        return where.toHtmlEscaped();
    return QStringLiteral("<a href=\"evidence:%1\">%2</a>").arg(index).arg(where.toHtmlEscaped());
}

} // namespace

DiagnosticDetail::DiagnosticDetail(QWidget *parent) : QTextBrowser(parent)
{
    setOpenLinks(false);
    setFrameShape(QFrame::NoFrame);
    setPlaceholderText(tr("Select a finding to see what it means and how to fix it."));
    connect(this, &QTextBrowser::anchorClicked, this, [this](const QUrl &url) {
        if (!m_finding || url.scheme() != QLatin1String("evidence"))
            return;
        const int index = url.path().toInt();
        if (index == 0)
            Q_EMIT evidenceRequested(m_finding->evidence);
        else if (index <= m_finding->related.size())
            Q_EMIT evidenceRequested(m_finding->related.at(index - 1).evidence);
    });
}

QSize DiagnosticDetail::sizeHint() const
{
    return {QTextBrowser::sizeHint().width(), fontMetrics().lineSpacing() * 4 + 2 * frameWidth()};
}

QSize DiagnosticDetail::minimumSizeHint() const
{
    return {QTextBrowser::minimumSizeHint().width(),
            fontMetrics().lineSpacing() * 2 + 2 * frameWidth()};
}

void DiagnosticDetail::showFinding(const std::optional<Diagnostic> &diagnostic,
                                   const QString &package, const std::optional<FindingMark> &mark)
{
    m_finding = diagnostic;
    if (!diagnostic) {
        clear();
        return;
    }
    const Diagnostic &d = *diagnostic;
    const DiagnosticKind kind = DiagnosticKind::of(d.code);
    QString html = QStringLiteral("<h3>%1</h3><p><b>%2</b> · <code>%3</code>%4</p><p>%5</p>")
                       .arg(kind.title.toHtmlEscaped(), DiagnosticModel::severityLabel(d.severity),
                            d.code.toHtmlEscaped(),
                            package.isEmpty() ? QString()
                                              : QStringLiteral(" · ") +
                                                    tr("package %1").arg(package.toHtmlEscaped()),
                            visibleText(d.message).toHtmlEscaped());
    if (!d.evidence.file.isEmpty())
        html += QStringLiteral("<p>%1</p>").arg(tr("At %1").arg(link(0, d.evidence)));
    if (!d.related.isEmpty()) {
        html += QStringLiteral("<p><b>%1</b></p><ul>").arg(tr("Related places"));
        for (int i = 0; i < d.related.size(); ++i)
            html += QStringLiteral("<li>%1 — %2</li>")
                        .arg(link(i + 1, d.related.at(i).evidence),
                             visibleText(d.related.at(i).message).toHtmlEscaped());
        html += QStringLiteral("</ul>");
    }
    if (!d.contexts.isEmpty()) {
        html += QStringLiteral("<p><b>%1</b></p><ul>")
                    .arg(d.contexts.size() == 1
                             ? tr("Seen in 1 system (root launch file)")
                             : tr("Seen in %1 systems (root launch files)").arg(d.contexts.size()));
        for (const QString &c : d.contexts)
            html += QStringLiteral("<li>%1</li>").arg(c.toHtmlEscaped());
        html += QStringLiteral("</ul>");
    }
    html += QStringLiteral("<p><b>%1</b><br/>%2</p>")
                .arg(tr("What this means"), kind.help.toHtmlEscaped());
    if (mark) {
        const QString who = mark->author.isEmpty() ? tr("someone") : mark->author;
        const QString when = QLocale().toString(mark->time.toLocalTime(), QLocale::ShortFormat);
        QString line = mark->status == FindingMark::Status::Accepted
                           ? tr("Accepted by %1 on %2.").arg(who, when)
                           : tr("Hidden by %1 on %2.").arg(who, when);
        if (!mark->reason.isEmpty())
            line += QLatin1Char(' ') + tr("Reason: %1").arg(mark->reason);
        html += QStringLiteral("<p><i>%1</i></p>").arg(line.toHtmlEscaped());
    }
    html +=
        QStringLiteral("<p><small>%1</small></p>").arg(tr("Key: %1").arg(d.key().toHtmlEscaped()));
    setHtml(html);
}

} // namespace rosarch
