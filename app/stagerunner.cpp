#include "stagerunner.h"
#include "nodeanalyzer.h"

#include <QMutex>
#include <QPromise>
#include <QtConcurrent>

#include <exception>

namespace rosarch {

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
    : QObject(parent), m_stage([](const QString &root, const StageControl &control) {
          return recoverAtomicNodes(root, control);
      })
{
}

StageRunner::~StageRunner()
{
    for (Watcher *w : std::as_const(m_watchers)) {
        w->disconnect(this);
        QFuture<AtomicNodeList> future = w->future();
        future.cancel();
        future.waitForFinished();
    }
}

void StageRunner::setStageFunction(StageFunction stage)
{
    m_stage = std::move(stage);
}

void StageRunner::run(const QString &root)
{
    if (m_current)
        m_current->future().cancel();
    const int generation = ++m_generation;
    auto progress = std::make_shared<Progress>();
    auto *watcher = new Watcher(this);
    m_current = watcher;
    m_watchers.append(watcher);
    connect(watcher, &Watcher::finished, this,
            [this, watcher, generation] { onFinished(watcher, generation); });
    connect(watcher, &Watcher::progressValueChanged, this,
            [this, progress, generation] { onProgress(progress, generation); });

    const StageFunction stage = m_stage;
    watcher->setFuture(
        QtConcurrent::run([stage, root, progress](QPromise<AtomicNodeList> &promise) {
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
            AtomicNodeList result;
            try {
                result = stage(root, control);
            } catch (const std::exception &e) {
                // A bug in a stage must not take the window down; show it as a diagnostic.
                result = {};
                result.workspaceRoot = root;
                Diagnostic d;
                d.severity = Diagnostic::Severity::Error;
                d.code = QStringLiteral("stage-failed");
                d.message = tr("Stage 1 stopped with an internal error: %1")
                                .arg(QString::fromLocal8Bit(e.what()));
                result.diagnostics.append(d);
            }
            if (!promise.isCanceled())
                promise.addResult(std::move(result));
        }));
    Q_EMIT stageStarted(root);
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

void StageRunner::onFinished(Watcher *watcher, int generation)
{
    m_watchers.removeOne(watcher);
    watcher->deleteLater();
    if (generation != m_generation)
        return; // superseded by a later run
    m_current = nullptr;
    const QFuture<AtomicNodeList> future = watcher->future();
    if (future.isCanceled() || future.resultCount() == 0) {
        Q_EMIT stageCanceled();
        return;
    }
    AtomicNodeList result = future.result();
    if (result.canceled) {
        Q_EMIT stageCanceled();
        return;
    }
    Q_EMIT stageFinished(result);
}

} // namespace rosarch
