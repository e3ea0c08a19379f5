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
    Architecture arch = Composer::run(nodes, launch, control.part(0, all), renamed);
    if (arch.canceled)
        return arch;
    arch.diagnostics = ArchitectureChecks::run(arch, nodes, launch);
    if (!launch.classifierInstances.isEmpty()) {
        LaunchDependencies alone;
        alone.instances = launch.classifierInstances;
        alone.nodes = launch.classifierNodes;
        Architecture classifiers =
            Composer::run(nodes, alone, control.part(int(launch.instances.size()), all), renamed);
        arch.canceled = classifiers.canceled;
        for (Composite &c : classifiers.composites)
            if (c.parentId.isEmpty())
                arch.classifiers.append(std::move(c));
    }
    return arch;
}

} // namespace rosarch
