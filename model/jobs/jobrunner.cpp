#include "jobs/jobrunner.h"

#include <QFutureWatcher>
#include <QMutex>
#include <QPromise>
#include <QtConcurrent>

#include <exception>
#include <limits>

namespace rosarch {

/// One job: its token, what the worker reported and the UI thread has not delivered yet, and
/// the watcher that brings its end back to the runner's thread.
struct JobRunner::Job
{
    int generation = 0;
    std::shared_ptr<std::atomic_bool> cancel = std::make_shared<std::atomic_bool>(false);
    ErasedDone done;
    QFutureWatcher<std::shared_ptr<void>> *watcher = nullptr;

    struct Progress
    {
        qint64 done = 0;
        qint64 total = 0;
        QString what;
        int step = 0;
    };

    QMutex mutex;
    /// The latest report of each step since the last delivery, in order: a step that ends
    /// between two deliveries still shows its last report, not only the next step's.
    QList<Progress> progress;
    QStringList lines;
    QString error;
    int tick = 0; ///< QFuture progress must grow: the future carries a tick, this the numbers
};

JobRunner::JobRunner(QObject *parent) : QObject(parent), m_pool(new QThreadPool(this))
{
    // the current job and superseded ones still finishing
    m_pool->setMaxThreadCount(4);
}

JobRunner::~JobRunner()
{
    for (const std::shared_ptr<Job> &job : std::as_const(m_jobs)) {
        job->watcher->disconnect(this);
        job->cancel->store(true);
        job->watcher->future().waitForFinished();
    }
}

int JobRunner::startErased(ErasedWork work, ErasedDone done)
{
    cancel();
    auto job = std::make_shared<Job>();
    job->generation = ++m_generation;
    job->done = std::move(done);
    job->watcher = new QFutureWatcher<std::shared_ptr<void>>(this);
    m_current = job;
    m_jobs.append(job);
    connect(job->watcher, &QFutureWatcherBase::progressValueChanged, this,
            [this, job] { deliver(job); });
    connect(job->watcher, &QFutureWatcherBase::finished, this, [this, job] { finish(job); });

    job->watcher->setFuture(QtConcurrent::run(
        m_pool, [work = std::move(work), job](QPromise<std::shared_ptr<void>> &promise) {
            promise.setProgressRange(0, std::numeric_limits<int>::max());
            const auto notify = [&promise, job] {
                int tick = 0;
                {
                    QMutexLocker lock(&job->mutex);
                    tick = ++job->tick;
                }
                promise.setProgressValue(tick);
            };
            JobControl control;
            control.m_cancel = job->cancel;
            control.m_progress = [job, notify](qint64 done, qint64 total, const QString &what,
                                               int step) {
                {
                    QMutexLocker lock(&job->mutex);
                    if (job->progress.isEmpty() || job->progress.last().step != step) {
                        if (job->progress.size() >= 8) // steps taking turns: a bound
                            job->progress.removeFirst();
                        job->progress.append({done, total, what, step});
                    } else
                        job->progress.last() = {done, total, what, step};
                }
                notify();
            };
            control.m_log = [job, notify](const QString &line) {
                {
                    QMutexLocker lock(&job->mutex);
                    job->lines << line;
                }
                notify();
            };
            std::shared_ptr<void> result;
            try {
                result = work(control);
            } catch (const std::exception &e) {
                QMutexLocker lock(&job->mutex);
                job->error = QString::fromLocal8Bit(e.what());
            } catch (...) {
                QMutexLocker lock(&job->mutex);
                job->error = QStringLiteral("unknown exception");
            }
            promise.addResult(std::move(result));
        }));
    return job->generation;
}

void JobRunner::cancel()
{
    if (m_current)
        m_current->cancel->store(true);
}

void JobRunner::deliver(const std::shared_ptr<Job> &job)
{
    if (job->generation != m_generation)
        return; // a newer job supersedes this one
    QStringList lines;
    QList<Job::Progress> progress;
    {
        QMutexLocker lock(&job->mutex);
        lines.swap(job->lines);
        progress.swap(job->progress);
    }
    for (const QString &line : std::as_const(lines))
        Q_EMIT logged(line);
    for (const Job::Progress &p : std::as_const(progress))
        Q_EMIT progressed(p.done, p.total, p.what, p.step);
}

void JobRunner::finish(const std::shared_ptr<Job> &job)
{
    m_jobs.removeOne(job);
    job->watcher->deleteLater();
    if (job->generation != m_generation)
        return;   // superseded by a later job
    deliver(job); // what arrived after the last tick
    m_current.reset();
    QString error;
    {
        QMutexLocker lock(&job->mutex);
        error = job->error;
    }
    if (!error.isEmpty()) {
        Q_EMIT failed(error);
        return;
    }
    const QFuture<std::shared_ptr<void>> future = job->watcher->future();
    const std::shared_ptr<void> result = future.resultCount() > 0 ? future.result() : nullptr;
    job->done(result, job->cancel->load());
}

} // namespace rosarch
