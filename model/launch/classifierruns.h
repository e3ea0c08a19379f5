#pragma once

#include "core/stagecontrol.h"
#include "launch/launchexecutor.h"

#include <QStringList>

#include <memory>
#include <optional>

namespace rosarch {

/// Each launch file of a system analysed on its own, with its declared defaults, in the
/// classifier scope: what its CCD shows. The files run on pool threads, each into its own
/// output, and are merged in the order asked for into what one executor running them one after
/// the other makes: the same ids ("clf1", "cn1", ...), the same containers (a LoadComposableNodes
/// finds its container among the nodes of the files before it too), the same budget cut.
class ClassifierRuns
{
public:
    static constexpr qsizetype kBudget = 100000; ///< instances over all runs

    /// `loader` must stay valid until finish() returns or the object is destroyed.
    ClassifierRuns(const Workspace &workspace, const AtomicNodeList &nodes,
                   LaunchExecutor::Loader loader, const StageControl &control,
                   qsizetype budget = kBudget);
    /// Stops the runs not begun and waits for those begun.
    ~ClassifierRuns();
    ClassifierRuns(const ClassifierRuns &) = delete;
    ClassifierRuns &operator=(const ClassifierRuns &) = delete;

    /// Begins running `files` (those finish() will likely be asked for) on pool threads while
    /// the caller does something else. The first start() says what the pool threads copy:
    /// `warm` (see finish()), else a new executor.
    void start(const QStringList &files, const LaunchExecutor *warm = nullptr);
    /// The runs of `files` in this order, into `out`'s classifierInstances and classifierNodes
    /// (left empty when the run is canceled); a run over the budget ends them with a
    /// diagnostic in `out`. What they would diagnose was found by the system's runs already:
    /// it is dropped. Each file is asked for once. The runs finish() makes itself use a copy of
    /// `warm` when given: an executor over the same workspace, nodes and loader, whose caches
    /// (include targets, parameter files) are filled already.
    void finish(const QStringList &files, LaunchDependencies *out,
                const LaunchExecutor *warm = nullptr);

private:
    /// What one file's run made, on its own.
    struct Run
    {
        bool ran = false; ///< false when it was canceled before it began
        LaunchDependencies made;
        QList<LaunchExecutor::UnfoundContainer> unfound;
    };
    struct State;

    static Run runFile(LaunchExecutor &executor, const StageControl &control, const QString &file);
    /// A pool thread's loop: runs the files no one runs yet until there are none.
    static void work(const std::shared_ptr<State> &state);
    /// The executor of the runs this thread makes.
    LaunchExecutor &executor(const LaunchExecutor *warm);
    /// Runs the files of `files` no pool thread has begun, from the last.
    void runWaiting(const QStringList &files, const LaunchExecutor *warm);
    /// `file`'s run: the pool's, waited for, or made now.
    Run take(const QString &file, const LaunchExecutor *warm);
    void stop();
    /// Appends `run` to `merged` as if its executor had run into `merged` all along.
    static void append(LaunchDependencies *merged, Run &run);

    std::shared_ptr<State> m_state;
    std::optional<LaunchExecutor> m_executor; ///< for the runs finish() makes itself
};

} // namespace rosarch
