#pragma once

#include "core/diagnostic.h"
#include "project/findingmark.h"

#include <QTextBrowser>

#include <optional>

namespace rosarch {

/// The explanation of the finding selected in the Log: its kind's title and help (what the
/// check means, how to fix it), the message, the evidence and related places as links to the
/// source, the systems it was seen in, its key and whether it is hidden or accepted.
class DiagnosticDetail : public QTextBrowser
{
    Q_OBJECT
public:
    explicit DiagnosticDetail(QWidget *parent = nullptr);

    /// Shows `diagnostic` (of `package`, with its mark); none clears the pane.
    void showFinding(const std::optional<Diagnostic> &diagnostic, const QString &package = {},
                     const std::optional<FindingMark> &mark = std::nullopt);
    const std::optional<Diagnostic> &finding() const { return m_finding; }

    /// A few lines: the pane sits under the findings, which keep most of a short Log.
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

Q_SIGNALS:
    /// A place of the finding was clicked.
    void evidenceRequested(const rosarch::Evidence &evidence);

private:
    std::optional<Diagnostic> m_finding;
};

} // namespace rosarch
