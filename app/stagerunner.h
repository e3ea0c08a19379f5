#pragma once

#include "core/atomicnodelist.h"
#include "core/launchdependencies.h"
#include "core/stagecontrol.h"
#include "jobs/jobrunner.h"
#include "launch/launchanalyzer.h"
#include "pipeline/recovery.h"
#include "pipeline/stageprocess.h"
#include "pipeline/stagesession.h"

#include <QObject>

#include <functional>
#include <memory>

namespace rosarch {

/// Runs the stages off the UI thread on a JobRunner and reports back on the UI thread: stages 1
/// to 3 together, or stages 2 and 3 against a stage 1 result. Starting a new run cancels the
/// previous one; its late result is dropped by the runner's generation number, so only the
/// latest run ever reports.
///
/// The stages run in the analysis worker process (StageProcess), so that a crash or a memory
/// blow-up in analysing somebody's code costs at most a file, and never the window: what the
/// worker cannot pin on one file arrives as stageFailed, and the previous result stays. The
/// worker is kept between runs (a StageSession, made by the first run), so a run after the
/// first pays neither its start nor the transfer of what did not change.
class StageRunner : public QObject
{
    Q_OBJECT
public:
    /// What a run computes.
    enum class Job
    {
        Recovery,   ///< stages 1 to 3
        LaunchOnly, ///< stage 2 against the given atomic nodes
    };
    Q_ENUM(Job)

    using RecoveryFunction =
        std::function<Recovery(const QString &root, const LaunchOptions &, const StageControl &)>;
    using LaunchFunction = std::function<LaunchDependencies(
        const QString &root, const AtomicNodeList &, const LaunchOptions &, const StageControl &)>;

    explicit StageRunner(QObject *parent = nullptr);

    /// Runs stages 1 to 3 in this process with `stage` instead of the worker; tests use slow
    /// or counting stages.
    void setStageFunction(RecoveryFunction stage);
    /// Runs the stage 2 re-run in this process with `stage` instead of the worker.
    void setLaunchFunction(LaunchFunction stage);
    /// How the worker is run (its path, the per-file time and memory budgets).
    void setProcessOptions(const StageProcess::Options &options);

    /// Starts stages 1 to 3 on `root`, superseding any run in progress. `shown` is the result
    /// the window shows now: a result equal to it is reported as unchanged (compared off the
    /// UI thread), so the views need not be rebuilt.
    void run(const QString &root, const LaunchOptions &options = {}, const Recovery &shown = {});
    /// True when the last stageFinished brought the same result as the one `run` was given.
    bool resultUnchanged() const { return m_unchanged; }
    /// Starts stage 2 alone on `root` against `nodes`, superseding any run in progress.
    void runLaunch(const QString &root, const AtomicNodeList &nodes, const LaunchOptions &options);
    /// Asks the current run to stop; stageCanceled follows once it has.
    void cancel();
    bool isRunning() const { return m_jobs.isRunning(); }
    /// The job of the run in progress (meaningless when none is).
    Job currentJob() const { return m_currentJob; }
    /// Incremented by every run; results of older generations are dropped.
    int generation() const { return m_jobs.generation(); }

Q_SIGNALS:
    void stageStarted(const QString &root, rosarch::StageRunner::Job job);
    /// Progress of `stage` (1 atomic nodes, 2 launch files, 3 composition; 0 = none named):
    /// `done` of `total` files (composites in stage 3), now on `what`.
    void stageProgressed(int done, int total, const QString &what, int stage);
    /// Stage `stage` of the run took `ms` milliseconds in the worker (before the result).
    void stageTimed(int stage, qint64 ms);
    /// Stages 1 and 2 finished (run()).
    void stageFinished(const rosarch::Recovery &result);
    /// Stage 2 alone finished (runLaunch()).
    void launchStageFinished(const rosarch::LaunchDependencies &result,
                             const rosarch::Architecture &architecture);
    void stageCanceled(rosarch::StageRunner::Job job);
    /// The run ended without a result (the worker stopped outside any one file's analysis);
    /// `message` says why, for a person.
    void stageFailed(rosarch::StageRunner::Job job, const QString &message);

private:
    /// A run's result, or why there is none.
    struct Outcome
    {
        Recovery recovery;
        QString error;
        QList<QPair<int, qint64>> stageTimes; ///< stage, milliseconds
        bool unchanged = false;               ///< the result equals the one shown
    };
    void start(const QString &root, Job job, std::function<Outcome(const StageControl &)> work);

    RecoveryFunction m_stage;     ///< in-process stages 1 to 3 (empty: the worker)
    LaunchFunction m_launchStage; ///< in-process stage 2 re-run (empty: the worker)
    StageProcess::Options m_process;
    /// The long-lived worker; shared with the runs, which may outlive a superseding run().
    std::shared_ptr<StageSession> session();
    std::shared_ptr<StageSession> m_session;
    Job m_currentJob = Job::Recovery;
    bool m_unchanged = false;
    JobRunner m_jobs; ///< last member: its destructor cancels and waits for the workers
};

} // namespace rosarch
