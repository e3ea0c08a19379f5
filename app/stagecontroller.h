#pragma once

#include "app/stagerunner.h"
#include "core/launchdependencies.h"
#include "launch/launchanalyzer.h"
#include "pipeline/recovery.h"

#include <QElapsedTimer>
#include <QObject>

namespace rosarch {

class Document;
class LogView;
class Traceability;

/// Runs the stages for the window: stages 1 and 2 when a workspace opens and on F5, stage 2
/// alone with the launch options a person chose. Puts results into the Document, keeps the
/// selection across runs, remembers launch options per workspace and writes the run log.
class StageController : public QObject
{
    Q_OBJECT
public:
    StageController(Document *document, StageRunner *runner, Traceability *traceability,
                    LogView *log, QObject *parent = nullptr);

    /// Switches to another workspace: an empty model, its project's launch options (else those
    /// remembered for it) and the selection of its last session (restored when the first
    /// result arrives).
    void setWorkspace(const QString &root);
    QString workspace() const { return m_workspace; }

    /// Runs stages 1 and 2 on the workspace with the current launch options.
    void runAll();
    /// Runs stage 2 alone against the current atomic nodes (both stages when there are none
    /// of this workspace yet, or while they are being recovered).
    void runLaunch();
    /// Stores `options` in the Document and the settings and runs stage 2 with them.
    void applyLaunchOptions(const LaunchOptions &options);
    /// "Stage 1 (atomic nodes)", for a person.
    static QString stageName(int stage);

Q_SIGNALS:
    /// A line for the status bar (0: until replaced).
    void statusMessage(const QString &text, int timeout);

private:
    void onStageStarted(const QString &root, StageRunner::Job job);
    void onStageFinished(const Recovery &result);
    void onLaunchStageFinished(const LaunchDependencies &result, const Architecture &architecture);
    void onStageCanceled(StageRunner::Job job);
    void onStageFailed(StageRunner::Job job, const QString &message);
    void rememberSelection();
    void restoreSelection();
    void report(const QString &summary);

    Document *m_document;
    StageRunner *m_runner;
    Traceability *m_traceability;
    LogView *m_log;
    QString m_workspace;
    QElapsedTimer m_runTimer;
    QString m_restoreNodeId; ///< selection to restore when the next result arrives
    QString m_restorePortId;
    QString m_restoreLaunchId;
};

} // namespace rosarch
