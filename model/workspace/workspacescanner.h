#pragma once

#include "core/stagecontrol.h"
#include "workspace/workspace.h"

namespace rosarch {

/// Walks a workspace folder: finds packages (package.xml), their build files and executables,
/// and the Python and C++ files to analyse. Never follows symlinked folders twice (loops are
/// reported), skips build/install/log and hidden folders.
class WorkspaceScanner
{
public:
    static Workspace scan(const QString &root, const StageControl &control = {});
};

} // namespace rosarch
