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

StageRunner::StageRunner(QObject *parent) : QObject(parent)
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
    const StageProcess::Options process = m_process;
    start(root, Job::Recovery, [stage, root, options, process](const StageControl &control) {
        Outcome out;
        Recovery &result = out.recovery;
        try {
            if (stage) {
                result = stage(root, options, control);
            } else if (StageProcess::helperPath(process.helperPath).isEmpty()) {
                result = recoverWorkspace(root, options, control);
                result.nodes.diagnostics.append(StageProcess::missingWorker());
            } else {
                StageProcess::Result r = StageProcess::recover(root, options, control, process);
                result = std::move(r.recovery);
                result.nodes.canceled = result.nodes.canceled || r.canceled;
                out.error = r.error;
            }
        } catch (const std::exception &e) {
            result = {};
            result.nodes.diagnostics.append(internalError(1, e));
        }
        if (result.nodes.workspaceRoot.isEmpty())
            result.nodes.workspaceRoot = root;
        return out;
    });
}

void StageRunner::runLaunch(const QString &root, const AtomicNodeList &nodes,
                            const LaunchOptions &options)
{
    const LaunchFunction stage = m_launchStage;
    const StageProcess::Options process = m_process;
    start(root, Job::LaunchOnly,
          [stage, root, nodes, options, process](const StageControl &control) {
              Outcome out;
              Recovery &result = out.recovery;
              try {
                  if (stage || StageProcess::helperPath(process.helperPath).isEmpty()) {
                      result.launch = stage ? stage(root, nodes, options, control)
                                            : analyzeLaunchFiles(root, nodes, options, control);
                      if (!result.launch.canceled && !control.isCanceled())
                          result.architecture = composeArchitecture(nodes, result.launch, control);
                  } else {
                      StageProcess::Result r =
                          StageProcess::launch(root, nodes, options, control, process);
                      result = std::move(r.recovery);
                      result.launch.canceled = result.launch.canceled || r.canceled;
                      out.error = r.error;
                  }
              } catch (const std::exception &e) {
                  result.launch = {};
                  result.launch.diagnostics.append(internalError(2, e));
              }
              return out;
          });
}

void StageRunner::start(const QString &root, Job job,
                        std::function<Outcome(const StageControl &)> work)
{
    m_currentJob = job;
    m_jobs.start<Outcome>([work = std::move(work)](
                              const JobControl &control) { return work(control.stageControl()); },
                          [this, job](Outcome out, bool canceled) {
                              const Recovery &result = out.recovery;
                              canceled = canceled ||
                                         (job == Job::Recovery ? result.nodes.canceled : false) ||
                                         result.launch.canceled;
                              if (canceled)
                                  Q_EMIT stageCanceled(job);
                              else if (!out.error.isEmpty())
                                  Q_EMIT stageFailed(job, out.error);
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
