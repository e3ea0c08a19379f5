#pragma once

#include "jobs/jobcontrol.h"

#include <QList>
#include <QObject>
#include <QThreadPool>

#include <functional>
#include <memory>

namespace rosarch {

/// Runs background work off the UI thread, one job of its kind at a time, for every kind of
/// background work (stages, suggestions, diagram layout). Starting a job cancels the one in
/// progress and makes it stale: a generation number drops its late result. Each job gets one
/// cancellation token and reports progress and log lines, delivered on the runner's thread.
/// Destroying the runner cancels every job and waits, so no worker outlives it.
class JobRunner : public QObject
{
    Q_OBJECT
public:
    explicit JobRunner(QObject *parent = nullptr);
    ~JobRunner() override;

    /// Starts `work` on the thread pool, superseding the job in progress. `done` is called on
    /// this runner's thread with the result, and whether the job was canceled before it
    /// returned (a canceled job may return what it has), unless a newer job superseded it or
    /// the work threw (then `failed` is emitted). Returns the job's generation.
    template <typename T>
    int start(std::function<T(const JobControl &)> work,
              std::function<void(T result, bool canceled)> done)
    {
        return startErased(
            [work = std::move(work)](const JobControl &control) -> std::shared_ptr<void> {
                return std::make_shared<T>(work(control));
            },
            [done = std::move(done)](const std::shared_ptr<void> &result, bool canceled) {
                done(result ? std::move(*std::static_pointer_cast<T>(result)) : T(), canceled);
            });
    }

    /// Asks the job in progress to stop; its `done` follows with `canceled` set.
    void cancel();
    bool isRunning() const { return m_current != nullptr; }
    /// Incremented by every start; results of older generations are dropped.
    int generation() const { return m_generation; }

Q_SIGNALS:
    /// The current job's latest progress (older jobs' progress is dropped); `step` as the job
    /// said (JobControl::progress).
    void progressed(qint64 done, qint64 total, const QString &what, int step);
    /// A log line of the current job.
    void logged(const QString &line);
    /// The current job threw; `message` says what. Its `done` is not called.
    void failed(const QString &message);

private:
    struct Job;
    using ErasedWork = std::function<std::shared_ptr<void>(const JobControl &)>;
    using ErasedDone = std::function<void(const std::shared_ptr<void> &, bool)>;

    int startErased(ErasedWork work, ErasedDone done);
    void deliver(const std::shared_ptr<Job> &job);
    void finish(const std::shared_ptr<Job> &job);

    /// The runner's own threads: a job blocks its thread for as long as it runs (the stages
    /// wait for the worker process), and on the global pool it would starve what Qt itself
    /// runs there; QPainter's parallel fills wait for it, so the window froze during a run.
    QThreadPool *m_pool;
    std::shared_ptr<Job> m_current;
    QList<std::shared_ptr<Job>> m_jobs; ///< every job whose worker has not finished yet
    int m_generation = 0;
};

} // namespace rosarch
