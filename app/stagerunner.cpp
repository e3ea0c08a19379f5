#include "app/stagerunner.h"
#include "jobs/disposal.h"

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
            [this](qint64 done, qint64 total, const QString &what, int step) {
                Q_EMIT stageProgressed(int(done), int(total), what, step);
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

void StageRunner::setProcessOptions(const StageProcess::Options &options)
{
    m_process = options;
    if (m_session)
        m_session->setOptions(options);
}

std::shared_ptr<StageSession> StageRunner::session()
{
    if (!m_session && !StageProcess::helperPath(m_process.helperPath).isEmpty())
        m_session = std::make_shared<StageSession>(m_process);
    return m_session;
}

void StageRunner::run(const QString &root, const LaunchOptions &options, const Recovery &shown)
{
    const RecoveryFunction stage = m_stage;
    const std::shared_ptr<StageSession> session = stage ? nullptr : this->session();
    start(root, Job::Recovery, [stage, session, root, options, shown](const StageControl &control) {
        Outcome out;
        Recovery &result = out.recovery;
        try {
            if (stage) {
                result = stage(root, options, control);
            } else if (!session) {
                result = recoverWorkspace(root, options, control);
                result.nodes.diagnostics.append(StageProcess::missingWorker());
            } else {
                StageProcess::Result r = session->recover(root, options, control);
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
        out.unchanged = !shown.nodes.workspaceRoot.isEmpty() && out.error.isEmpty() &&
                        !control.isCanceled() && result == shown;
        return out;
    });
}

void StageRunner::runLaunch(const QString &root, const AtomicNodeList &nodes,
                            const LaunchOptions &options)
{
    const LaunchFunction stage = m_launchStage;
    const std::shared_ptr<StageSession> session = stage ? nullptr : this->session();
    start(root, Job::LaunchOnly,
          [stage, session, root, nodes, options](const StageControl &control) {
              Outcome out;
              Recovery &result = out.recovery;
              try {
                  if (stage || !session) {
                      result = recoverLaunch(root, nodes, options, control, nullptr, stage);
                  } else {
                      StageProcess::Result r = session->launch(root, nodes, options, control);
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
    m_jobs.start<Outcome>(
        [work = std::move(work)](const JobControl &control) {
            // The stage times arrive on this thread (the worker's frames are read here).
            QList<QPair<int, qint64>> times;
            StageControl stages = control.stageControl();
            stages.stageTimed = [&times](int stage, qint64 ms) { times.append({stage, ms}); };
            Outcome out = work(stages);
            out.stageTimes = times;
            return out;
        },
        [this, job](Outcome out, bool canceled) {
            for (const auto &[stage, ms] : std::as_const(out.stageTimes))
                Q_EMIT stageTimed(stage, ms);
            const Recovery &result = out.recovery;
            m_unchanged = out.unchanged;
            canceled = canceled || (job == Job::Recovery ? result.nodes.canceled : false) ||
                       result.launch.canceled;
            if (canceled)
                Q_EMIT stageCanceled(job);
            else if (!out.error.isEmpty())
                Q_EMIT stageFailed(job, out.error);
            else if (job == Job::Recovery)
                Q_EMIT stageFinished(result);
            else
                Q_EMIT launchStageFinished(result.launch, result.architecture);
            disposeInBackground(std::move(out.recovery));
        });
    Q_EMIT stageStarted(root, job);
}

void StageRunner::cancel()
{
    m_jobs.cancel();
}

} // namespace rosarch
