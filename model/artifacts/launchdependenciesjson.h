#pragma once

#include "core/launchdependencies.h"

#include <QByteArray>

namespace rosarch {

/// The Launch File Dependency Description as JSON (blueprint §2: list_launch_file,
/// list_atom_node_instances; with remaps, parameters, conditions, unresolved items and
/// evidence added). Deterministic.
namespace LaunchDependenciesJson {
QByteArray write(const LaunchDependencies &launch);
}

} // namespace rosarch
