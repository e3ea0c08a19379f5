#include "recovery.h"
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
    return r;
}

LaunchDependencies analyzeLaunchFiles(const QString &root, const AtomicNodeList &nodes,
                                      const LaunchOptions &options, const StageControl &control)
{
    const Workspace ws = WorkspaceScanner::scan(root, control);
    return LaunchAnalyzer::run(ws, nodes, options, control);
}

} // namespace rosarch
