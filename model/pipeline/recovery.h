#pragma once

#include "atomicnodelist.h"
#include "composition.h"
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
    Architecture architecture; ///< stage 3
};

/// Runs stages 1, 2 and 3 on `root` (one scan, shared).
Recovery recoverWorkspace(const QString &root, const LaunchOptions &options = {},
                          const StageControl &control = {});

} // namespace rosarch
