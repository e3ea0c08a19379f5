#pragma once

#include "atomicnodelist.h"
#include "launchdependencies.h"
#include "workspace.h"

namespace rosarch {

/// Executables that build a system of their own (blueprint §1, "Nodes built in code"): a main
/// that constructs several node classes and hands them to an executor. Each such executable is
/// run as if a launch file held one Node action of it, on its own in the classifier scope, so
/// that the system `ros2 run pkg exe` starts gets a CCD. The runs are appended to `out`'s
/// classifier instances (format "executable", type the executable's name, file its main
/// source) and nodes.
void addExecutableSystems(const Workspace &workspace, const AtomicNodeList &nodes,
                          LaunchDependencies *out);

} // namespace rosarch
