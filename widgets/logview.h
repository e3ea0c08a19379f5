#pragma once

#include "evidence.h"

#include <QWidget>

class QPlainTextEdit;
class QSplitter;
class QTreeView;

namespace rosarch {

class DiagnosticModel;

/// The "Log" panel: the diagnostics of the last run beside the run's progress lines.
class LogView : public QWidget
{
    Q_OBJECT
public:
    explicit LogView(QWidget *parent = nullptr);

    void setModel(DiagnosticModel *model);
    QTreeView *diagnosticsView() const { return m_diagnostics; }
    QPlainTextEdit *logEdit() const { return m_log; }
    QSplitter *splitter() const { return m_splitter; }

    /// Appends one line (with the time) to the run log.
    void appendLog(const QString &line);
    void clearLog();

    /// Moves to the next / previous diagnostic (wrapping) and shows its evidence.
    void selectNextDiagnostic();
    void selectPreviousDiagnostic();

Q_SIGNALS:
    /// A diagnostic with a location was selected or activated.
    void evidenceRequested(const Evidence &evidence);

private:
    void step(int delta);
    void onCurrentChanged(const QModelIndex &current);

    DiagnosticModel *m_model = nullptr;
    QSplitter *m_splitter;
    QTreeView *m_diagnostics;
    QPlainTextEdit *m_log;
};

} // namespace rosarch
