#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"
#include "core/stagecontrol.h"
#include "launch/launchanalyzer.h"

#include <QString>

#include <functional>

namespace rosarch {

/// The artifacts of every stage run so far on one workspace.
struct Recovery
{
    AtomicNodeList nodes;      ///< stage 1
    LaunchDependencies launch; ///< stage 2
    Architecture architecture; ///< stage 3

    bool operator==(const Recovery &) const = default;
};

/// The figures of a recovery that the command line, the log and the status bar report.
struct RecoveryCounts
{
    qsizetype packages = 0;
    qsizetype nodes = 0;   ///< atomic node classes (pluginlib plugins excluded)
    qsizetype plugins = 0; ///< pluginlib plugin classifiers
    qsizetype ports = 0;
    qsizetype launchFiles = 0;
    qsizetype launchInstances = 0; ///< launch-file instances
    qsizetype nodeInstances = 0;
    qsizetype unresolved = 0; ///< items of launch-file and node instances stage 2 could not resolve
    qsizetype composites = 0;
    qsizetype diagnostics = 0; ///< of all three stages
    qsizetype errors = 0;      ///< diagnostics of severity Error

    static RecoveryCounts of(const Recovery &recovery);
};

/// Called with the recovery so far when stage 1 or stage 2 is done and the run goes on.
using StageDone = std::function<void(int stage, const Recovery &sofar)>;

/// Runs stages 1, 2 and 3 on `root` (one scan, shared). With `previous` (an earlier complete
/// recovery), stage 3 is not run again when its inputs, stages 1 and 2, equal the ones
/// `previous` was composed from but for source locations: see composeOrReuse(). The stages
/// keep their results in the cache `control` names, else in the process's
/// (AnalysisCache::shared()).
Recovery recoverWorkspace(const QString &root, const LaunchOptions &options = {},
                          const StageControl &control = {}, const Recovery *previous = nullptr,
                          const StageDone &stageDone = {});

/// Stage 2 on its own: analyzeLaunchFiles(), or what a test runs in its place.
using LaunchStage = std::function<LaunchDependencies(const QString &root, const AtomicNodeList &,
                                                     const LaunchOptions &, const StageControl &)>;

/// Runs stages 2 and 3 on `root` against the stage 1 result `nodes`, as after an edit that
/// leaves stage 1's result as it was: the Recovery holds their results (its `nodes` stay
/// empty). Stage 3 is composeOrReuse() with `previous`; `launchStage` stands in for
/// analyzeLaunchFiles() when given. The cache is chosen as by recoverWorkspace().
Recovery recoverLaunch(const QString &root, const AtomicNodeList &nodes,
                       const LaunchOptions &options = {}, const StageControl &control = {},
                       const Recovery *previous = nullptr, const LaunchStage &launchStage = {});

/// Stage 3 on `nodes` and `launch`, or `previous`'s architecture when it was composed from equal
/// ones (stage 3 is a function of them alone), or from ones that differ only in where some
/// locations moved in a way stage 3 cannot tell (EvidenceShift): then with them moved too.
Architecture composeOrReuse(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                            const StageControl &control, const Recovery *previous);

} // namespace rosarch
