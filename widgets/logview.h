#pragma once

#include "core/evidence.h"

#include <QModelIndexList>
#include <QWidget>

class QAction;

class QPlainTextEdit;
class QSortFilterProxyModel;
class QSplitter;
class QTreeView;

namespace rosarch {

class DiagnosticDetail;
class DiagnosticFilterBar;
class DiagnosticModel;

/// The "Log" panel: the findings of the last run as a table to work through (filter, sort,
/// group, hide, accept; the selected one explained below it) beside the run's progress lines.
class LogView : public QWidget
{
    Q_OBJECT
public:
    explicit LogView(QWidget *parent = nullptr);

    void setModel(DiagnosticModel *model);
    QTreeView *diagnosticsView() const { return m_diagnostics; }
    QPlainTextEdit *logEdit() const { return m_log; }
    QSplitter *splitter() const { return m_splitter; }
    DiagnosticFilterBar *filterBar() const { return m_filterBar; }
    DiagnosticDetail *detail() const { return m_detail; }
    QAction *hideAction() const { return m_hide; }
    QAction *acceptAction() const { return m_accept; }
    QAction *restoreAction() const { return m_restore; }
    QAction *acceptExternalAction() const { return m_acceptExternal; }

    /// Appends one line (with the time) to the run log.
    void appendLog(const QString &line);
    void clearLog();

    /// Moves to the next / previous finding shown (wrapping, in the order of the view: the
    /// filter, the sort and the groups apply) and shows its evidence.
    void selectNextDiagnostic();
    void selectPreviousDiagnostic();

    /// "Log — 1,523 findings, 212 shown": what the dock's title says.
    QString title() const;

Q_SIGNALS:
    /// A diagnostic with a location was selected or activated.
    void evidenceRequested(const Evidence &evidence);
    /// The counts in title() changed.
    void titleChanged(const QString &title);
    /// The person accepted the selected findings' ports as expected externals: the
    /// declarations for the project ("input /scan" and the like, see Diagnostic::external).
    void externalsAccepted(const QStringList &declarations);

private:
    void step(int delta);
    void onCurrentChanged(const QModelIndex &current);
    void showCurrent();
    void afterReset();
    void markSelected(int status, bool askReason);
    QModelIndexList selectedFindings() const;
    QStringList selectedExternals() const;

    DiagnosticModel *m_model = nullptr;
    QSortFilterProxyModel *m_proxy;
    QSplitter *m_splitter;
    QWidget *m_findings;
    DiagnosticFilterBar *m_filterBar = nullptr;
    QSplitter *m_findingsSplitter;
    QTreeView *m_diagnostics;
    DiagnosticDetail *m_detail;
    QPlainTextEdit *m_log;
    QAction *m_hide;
    QAction *m_accept;
    QAction *m_acceptWithReason;
    QAction *m_restore;
    QAction *m_acceptExternal;
    QString m_currentKey;   ///< kept across a reset of the table (a filter change, a re-run)
    bool m_grouped = false; ///< as the table was last laid out (rows indented under groups)
};

} // namespace rosarch
