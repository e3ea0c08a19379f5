#include "stagerunner.h"
#include "composearchitecture.h"

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
    connect(&m_jobs, &JobRunner::progressed, this,
            [this](qint64 done, qint64 total, const QString &what) {
                Q_EMIT stageProgressed(int(done), int(total), what);
            });
    // The stage functions turn exceptions into diagnostics; anything else ends the run.
    connect(&m_jobs, &JobRunner::failed, this, [this] { Q_EMIT stageCanceled(m_currentJob); });
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

void StageRunner::start(const QString &root, Job job,
                        std::function<Recovery(const StageControl &)> work)
{
    m_currentJob = job;
    m_jobs.start<Recovery>([work = std::move(work)](
                               const JobControl &control) { return work(control.stageControl()); },
                           [this, job](Recovery result, bool canceled) {
                               canceled = canceled ||
                                          (job == Job::Recovery ? result.nodes.canceled : false) ||
                                          result.launch.canceled;
                               if (canceled)
                                   Q_EMIT stageCanceled(job);
                               else if (job == Job::Recovery)
                                   Q_EMIT stageFinished(result);
                               else
                                   Q_EMIT launchStageFinished(result.launch, result.architecture);
                           });
    Q_EMIT stageStarted(root, job);
}

void StageRunner::cancel()
{
    m_jobs.cancel();
}

} // namespace rosarch
