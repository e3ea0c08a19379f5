#include "composearchitecture.h"
#include "architecturechecks.h"
#include "composer.h"

namespace rosarch {

Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control,
                                 const QHash<QString, QString> &renamed)
{
    Architecture arch = Composer::run(nodes, launch, control, renamed);
    if (arch.canceled)
        return arch;
    arch.diagnostics = ArchitectureChecks::run(arch, nodes, launch);
    if (!launch.classifierInstances.isEmpty()) {
        LaunchDependencies alone;
        alone.instances = launch.classifierInstances;
        alone.nodes = launch.classifierNodes;
        Architecture classifiers = Composer::run(nodes, alone, control, renamed);
        arch.canceled = classifiers.canceled;
        for (Composite &c : classifiers.composites)
            if (c.parentId.isEmpty())
                arch.classifiers.append(std::move(c));
    }
    return arch;
}

} // namespace rosarch
