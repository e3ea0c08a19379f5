#pragma once

#include "atomicnodelist.h"
#include "stagecontrol.h"

#include <QFutureWatcher>
#include <QObject>

#include <functional>
#include <memory>

namespace rosarch {

/// Runs stage 1 off the UI thread (QtConcurrent + QPromise) and reports back on the UI
/// thread. Starting a new run cancels the previous one; its late result is dropped by
/// comparing generation numbers, so only the latest run ever reports.
class StageRunner : public QObject
{
    Q_OBJECT
public:
    using StageFunction = std::function<AtomicNodeList(const QString &root, const StageControl &)>;

    explicit StageRunner(QObject *parent = nullptr);
    /// Cancels what still runs and waits for it; no worker outlives the runner.
    ~StageRunner() override;

    /// Replaces the stage (default: recoverAtomicNodes); tests use slow or counting stages.
    void setStageFunction(StageFunction stage);

    /// Starts stage 1 on `root`, superseding any run in progress.
    void run(const QString &root);
    /// Asks the current run to stop; stageCanceled follows once it has.
    void cancel();
    bool isRunning() const { return m_current != nullptr; }
    /// Incremented by every run(); results of older generations are dropped.
    int generation() const { return m_generation; }

Q_SIGNALS:
    void stageStarted(const QString &root);
    void stageProgressed(int done, int total, const QString &what);
    void stageFinished(const rosarch::AtomicNodeList &result);
    void stageCanceled();

private:
    struct Progress;
    using Watcher = QFutureWatcher<AtomicNodeList>;

    void onFinished(Watcher *watcher, int generation);
    void onProgress(const std::shared_ptr<Progress> &progress, int generation);

    StageFunction m_stage;
    Watcher *m_current = nullptr;
    QList<Watcher *> m_watchers; ///< every run whose worker has not finished yet
    int m_generation = 0;
};

} // namespace rosarch
