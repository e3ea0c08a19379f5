#pragma once

#include "core/atomicnodelist.h"

#include <QStringList>

namespace rosarch {

/// What must hold of every recovered model, whatever the input: checked over every
/// fixture by the tests and over real repositories by scripts/check-invariants.py.
/// - a node name is a ROS name or empty (unresolved), never a variable's name;
/// - a port name that is not an expression is a ROS name (with `{plugin}` / `{node}`), never an
///   enum constant or C++ text;
/// - no class lists the same port (kind, name, type, place) twice.
/// Returns one line per violation, "" when all hold.
QStringList modelInvariantViolations(const AtomicNodeList &nodes);

} // namespace rosarch
