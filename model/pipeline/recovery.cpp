#include "recovery.h"
#include "composearchitecture.h"
#include "nodeanalyzer.h"
#include "workspacescanner.h"

namespace rosarch {

RecoveryCounts RecoveryCounts::of(const Recovery &r)
{
    RecoveryCounts c;
    c.packages = r.nodes.packages.size();
    for (const AtomicNode &n : r.nodes.nodes) {
        (n.isPlugin() ? c.plugins : c.nodes) += 1;
        c.ports += n.ports.size();
    }
    c.launchFiles = r.launch.launchFiles.size();
    c.launchInstances = r.launch.instances.size();
    c.nodeInstances = r.launch.nodes.size();
    for (const LaunchFileInstance &i : r.launch.instances)
        c.unresolved += i.unresolved.size();
    for (const NodeInstance &i : r.launch.nodes)
        c.unresolved += i.unresolved.size();
    c.composites = r.architecture.composites.size();
    for (const QList<Diagnostic> *list :
         {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics}) {
        c.diagnostics += list->size();
        for (const Diagnostic &d : *list)
            c.errors += d.severity == Diagnostic::Severity::Error ? 1 : 0;
    }
    return c;
}

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
