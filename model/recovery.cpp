#include "recovery.h"
#include "architecturechecks.h"
#include "composer.h"
#include "nodeanalyzer.h"
#include "workspacescanner.h"

namespace rosarch {

Recovery recoverWorkspace(const QString &root, const LaunchOptions &options, const StageControl &control)
{
    Recovery r;
    const Workspace ws = WorkspaceScanner::scan(root, control);
    r.nodes = NodeAnalyzer::run(ws, control);
    if (r.nodes.canceled || control.isCanceled()) {
        r.launch.canceled = true;
        return r;
    }
    r.launch = LaunchAnalyzer::run(ws, r.nodes, options, control);
    if (r.launch.canceled || control.isCanceled())
        return r;
    r.architecture = composeArchitecture(r.nodes, r.launch, control);
    return r;
}

Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control)
{
    Architecture arch = Composer::run(nodes, launch, control);
    if (!arch.canceled)
        arch.diagnostics = ArchitectureChecks::run(arch, nodes, launch);
    return arch;
}

LaunchDependencies analyzeLaunchFiles(const QString &root, const AtomicNodeList &nodes,
                                      const LaunchOptions &options, const StageControl &control)
{
    const Workspace ws = WorkspaceScanner::scan(root, control);
    return LaunchAnalyzer::run(ws, nodes, options, control);
}

} // namespace rosarch
