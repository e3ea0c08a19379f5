#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"
#include "core/stagecontrol.h"

#include <QHash>

namespace rosarch {

/// Stage 3: the composites of every launch-file instance plus the architecture checks.
/// `renamed`: topics, services and actions a person renamed (Composer::run).
Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control = {},
                                 const QHash<QString, QString> &renamed = {});

} // namespace rosarch
