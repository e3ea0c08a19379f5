#pragma once

#include "atomicnodelist.h"
#include "composition.h"
#include "launchdependencies.h"
#include "stagecontrol.h"

namespace rosarch {

/// Stage 3: the composites of every launch-file instance plus the architecture checks.
Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control = {});

} // namespace rosarch
