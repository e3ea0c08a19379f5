#pragma once

#include "pipeline/recovery.h"
#include "pipeline/stageprocess.h"
#include "pipeline/workerprocess.h"

#include <QMutex>

namespace rosarch {

struct StageRequest;

/// A long-lived analysis worker (rosarch-stages) kept between runs, supervised as
/// StageProcess describes: a run on an already running worker pays neither the process start
/// nor sending what did not change (the worker replies with the parts of the result that
/// differ from its previous reply). The worker is started ahead of need (at construction), and
/// again after a crash, an overrun, a kill or a cancel; it leaves when the session goes.
/// Thread-safe: runs from several threads take turns, each getting its own result.
class StageSession
{
public:
    explicit StageSession(const StageProcess::Options &options = {}, bool startNow = true);
    StageSession(const StageSession &) = delete;
    StageSession &operator=(const StageSession &) = delete;
    ~StageSession();

    /// Changes how the worker runs; a different program or memory budget restarts it.
    void setOptions(const StageProcess::Options &options);

    /// Stages 1 to 3 on `root`.
    StageProcess::Result recover(const QString &root, const LaunchOptions &options,
                                 const StageControl &control);
    /// Stages 2 and 3 on `root` against stage 1's `nodes`.
    StageProcess::Result launch(const QString &root, const AtomicNodeList &nodes,
                                const LaunchOptions &options, const StageControl &control);

    /// Lets the worker go without waiting for it to leave (WorkerProcess::release): for a
    /// session of one run, whose worker still writes its cache after it replied.
    void releaseWorker();

    /// The worker's process id (-1 when none runs), and how many the session started: for tests.
    qint64 workerPid();
    int workersStarted();

private:
    struct Attempt;
    StageProcess::Result supervise(StageRequest request, const StageControl &control);
    Attempt attempt(const StageRequest &request, const StageControl &control);
    /// The result of the stages an attempt finished before its worker stopped outside any file.
    static Recovery partial(const Attempt &a, const QString &why);
    bool ensureWorker(QString *error);

    QMutex m_mutex; ///< one run at a time
    StageProcess::Options m_options;
    QString m_helper;
    WorkerProcess m_worker;
    Recovery m_base;           ///< the worker's previous reply, which its next one is relative to
    bool m_baseIsEmpty = true; ///< no previous reply: the next one comes in full
    int m_started = 0;
};

} // namespace rosarch
