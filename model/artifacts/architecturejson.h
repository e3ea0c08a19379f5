#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"

#include <QByteArray>
#include <QMap>

namespace rosarch {

/// Stage 3's architecture as JSON: every composite (one per launch-file instance) with its
/// parts, resolved ports, channels, boundary ports and connections, each with evidence; the
/// representative composite of each launch file names its CCD file. With the node list and
/// the launch dependencies, each node part lists its parameters (declaration joined with the
/// value in effect, ParameterView). Deterministic.
namespace ArchitectureJson {
QByteArray write(const Architecture &arch, const QMap<QString, QString> &ccdStems = {},
                 const AtomicNodeList *nodes = nullptr, const LaunchDependencies *launch = nullptr);
}

} // namespace rosarch
