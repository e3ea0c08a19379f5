#include "recovery.h"
#include "composearchitecture.h"
#include "nodeanalyzer.h"
#include "workspacescanner.h"

namespace rosarch {

Recovery recoverWorkspace(const QString &root, const LaunchOptions &options,
                          const StageControl &control)
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

} // namespace rosarch
