#include "composearchitecture.h"
#include "architecturechecks.h"
#include "composer.h"

namespace rosarch {

Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control,
                                 const QHash<QString, QString> &renamed)
{
    // One progression for the stage: the systems, then the launch files' own classifiers.
    const int all = int(launch.instances.size() + launch.classifierInstances.size());
    const auto part = [&control, all](int before) {
        StageControl c = control;
        if (control.progressed)
            c.progressed = [&control, all, before](int done, int, const QString &what) {
                control.report(before + done, all, what);
            };
        return c;
    };
    Architecture arch = Composer::run(nodes, launch, part(0), renamed);
    if (arch.canceled)
        return arch;
    arch.diagnostics = ArchitectureChecks::run(arch, nodes, launch);
    if (!launch.classifierInstances.isEmpty()) {
        LaunchDependencies alone;
        alone.instances = launch.classifierInstances;
        alone.nodes = launch.classifierNodes;
        Architecture classifiers =
            Composer::run(nodes, alone, part(int(launch.instances.size())), renamed);
        arch.canceled = classifiers.canceled;
        for (Composite &c : classifiers.composites)
            if (c.parentId.isEmpty())
                arch.classifiers.append(std::move(c));
    }
    return arch;
}

} // namespace rosarch
