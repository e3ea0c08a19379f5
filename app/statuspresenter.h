#pragma once

#include <QObject>
#include <QString>

class QAction;
class QFrame;
class QLabel;
class QMainWindow;
class QProgressBar;
class QToolButton;

namespace rosarch {

class Document;
class PanelDocks;
class StageController;
class StageRunner;
struct RecoveryCounts;

/// What the window says about the analysis: the status bar's counts of what the stages found,
/// the progress of a run with its cancel button, and the texts of the panels while they are
/// empty.
class StatusPresenter : public QObject
{
    Q_OBJECT
public:
    StatusPresenter(QMainWindow *window, Document *document, StageRunner *runner,
                    const StageController *stages, PanelDocks *docks, QAction *cancelAction);

    /// Shows the counts of the current model (and the empty panels' texts); returns them.
    RecoveryCounts updateCounts();
    /// What the empty panels say: open a workspace, reading, stopped before a result, no
    /// package here, no node classes, no launch files.
    void updatePlaceholders();
    /// Shows the progress and the cancel button while a stage runs, the counts otherwise.
    void setRunning(bool running);

private:
    void onStageStarted();
    void onStageProgressed(int done, int total, const QString &what, int stage);
    void onStageEnded(bool stopped);

    QMainWindow *m_window;
    Document *m_document;
    StageRunner *m_runner;
    const StageController *m_stages;
    PanelDocks *m_docks;
    QAction *m_cancelAction;
    QLabel *m_countsLabel;
    QFrame *m_countsSeparator;
    QProgressBar *m_progressBar;
    QToolButton *m_cancelButton;
    bool m_runStopped = false; ///< the last run was canceled or failed
    QString m_lastProgressText;
};

} // namespace rosarch
