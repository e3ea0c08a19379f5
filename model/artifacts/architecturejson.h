#pragma once

#include "composition.h"

#include <QByteArray>
#include <QMap>

namespace rosarch {

/// Stage 3's architecture as JSON: every composite (one per launch-file instance) with its
/// parts, resolved ports, channels, boundary ports and connections, each with evidence; the
/// representative composite of each launch file names its CCD file. Deterministic.
namespace ArchitectureJson {
QByteArray write(const Architecture &arch, const QMap<QString, QString> &ccdStems = {});
}

} // namespace rosarch
