#pragma once

#include "atomicnodelist.h"
#include "launchanalyzer.h"
#include "launchdependencies.h"
#include "stagecontrol.h"

#include <QString>

namespace rosarch {

/// The artifacts of every stage run so far on one workspace.
struct Recovery
{
    AtomicNodeList nodes;      ///< stage 1
    LaunchDependencies launch; ///< stage 2
};

/// Runs stages 1 and 2 on `root` (one scan, shared).
Recovery recoverWorkspace(const QString &root, const LaunchOptions &options = {},
                          const StageControl &control = {});

} // namespace rosarch
