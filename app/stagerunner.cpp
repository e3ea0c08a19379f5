#include "stagerunner.h"
#include "composearchitecture.h"

#include <QMutex>
#include <QPromise>
#include <QtConcurrent>

#include <exception>

namespace rosarch {

namespace {

Diagnostic internalError(int stage, const std::exception &e)
{
    // A bug in a stage must not take the window down; show it as a diagnostic.
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.code = QStringLiteral("stage-failed");
    d.message = StageRunner::tr("Stage %1 stopped with an internal error: %2")
                    .arg(stage)
                    .arg(QString::fromLocal8Bit(e.what()));
    return d;
}

} // namespace

/// The latest progress report of one run. QFuture progress values must grow, but a stage
/// may restart its count per phase, so the future only carries a tick and this the numbers.
struct StageRunner::Progress
{
    QMutex mutex;
    int done = 0;
    int total = 0;
    QString what;
    int tick = 0;
};

StageRunner::StageRunner(QObject *parent)
    : QObject(parent),
      m_stage([](const QString &root, const LaunchOptions &options, const StageControl &control) {
          return recoverWorkspace(root, options, control);
      }),
      m_launchStage([](const QString &root, const AtomicNodeList &nodes,
                       const LaunchOptions &options, const StageControl &control) {
          return analyzeLaunchFiles(root, nodes, options, control);
      })
{
}

StageRunner::~StageRunner()
{
    for (Watcher *w : std::as_const(m_watchers)) {
        w->disconnect(this);
        QFuture<Recovery> future = w->future();
        future.cancel();
        future.waitForFinished();
    }
}

void StageRunner::setStageFunction(RecoveryFunction stage)
{
    m_stage = std::move(stage);
}

void StageRunner::setLaunchFunction(LaunchFunction stage)
{
    m_launchStage = std::move(stage);
}

void StageRunner::run(const QString &root, const LaunchOptions &options)
{
    const RecoveryFunction stage = m_stage;
    start(root, Job::Recovery, [stage, root, options](const StageControl &control) {
        Recovery result;
        try {
            result = stage(root, options, control);
        } catch (const std::exception &e) {
            result = {};
            result.nodes.diagnostics.append(internalError(1, e));
        }
        if (result.nodes.workspaceRoot.isEmpty())
            result.nodes.workspaceRoot = root;
        return result;
    });
}

void StageRunner::runLaunch(const QString &root, const AtomicNodeList &nodes,
                            const LaunchOptions &options)
{
    const LaunchFunction stage = m_launchStage;
    start(root, Job::LaunchOnly, [stage, root, nodes, options](const StageControl &control) {
        Recovery result;
        try {
            result.launch = stage(root, nodes, options, control);
            if (!result.launch.canceled && !control.isCanceled())
                result.architecture = composeArchitecture(nodes, result.launch, control);
        } catch (const std::exception &e) {
            result.launch = {};
            result.launch.diagnostics.append(internalError(2, e));
        }
        return result;
    });
}

void StageRunner::start(const QString &root, Job job, Work work)
{
    if (m_current)
        m_current->future().cancel();
    const int generation = ++m_generation;
    auto progress = std::make_shared<Progress>();
    auto *watcher = new Watcher(this);
    m_current = watcher;
    m_currentJob = job;
    m_watchers.append(watcher);
    connect(watcher, &Watcher::finished, this,
            [this, watcher, generation, job] { onFinished(watcher, generation, job); });
    connect(watcher, &Watcher::progressValueChanged, this,
            [this, progress, generation] { onProgress(progress, generation); });

    watcher->setFuture(QtConcurrent::run([work, progress](QPromise<Recovery> &promise) {
        StageControl control;
        control.canceled = [&promise] { return promise.isCanceled(); };
        control.progressed = [&promise, progress](int done, int total, const QString &what) {
            int tick = 0;
            {
                QMutexLocker lock(&progress->mutex);
                progress->done = done;
                progress->total = total;
                progress->what = what;
                tick = ++progress->tick;
            }
            promise.setProgressValueAndText(tick, what);
        };
        Recovery result = work(control);
        if (!promise.isCanceled())
            promise.addResult(std::move(result));
    }));
    Q_EMIT stageStarted(root, job);
}

void StageRunner::cancel()
{
    if (m_current)
        m_current->future().cancel();
}

void StageRunner::onProgress(const std::shared_ptr<Progress> &progress, int generation)
{
    if (generation != m_generation)
        return;
    int done = 0;
    int total = 0;
    QString what;
    {
        QMutexLocker lock(&progress->mutex);
        if (progress->tick == 0)
            return; // the watcher replays the initial state before the stage reports anything
        done = progress->done;
        total = progress->total;
        what = progress->what;
    }
    Q_EMIT stageProgressed(done, total, what);
}

void StageRunner::onFinished(Watcher *watcher, int generation, Job job)
{
    m_watchers.removeOne(watcher);
    watcher->deleteLater();
    if (generation != m_generation)
        return; // superseded by a later run
    m_current = nullptr;
    const QFuture<Recovery> future = watcher->future();
    if (future.isCanceled() || future.resultCount() == 0) {
        Q_EMIT stageCanceled(job);
        return;
    }
    const Recovery result = future.result();
    const bool canceled = job == Job::Recovery ? result.nodes.canceled || result.launch.canceled
                                               : result.launch.canceled;
    if (canceled) {
        Q_EMIT stageCanceled(job);
        return;
    }
    if (job == Job::Recovery)
        Q_EMIT stageFinished(result);
    else
        Q_EMIT launchStageFinished(result.launch, result.architecture);
}

} // namespace rosarch
