#include "composearchitecture.h"
#include "architecturechecks.h"
#include "composer.h"

namespace rosarch {

Architecture composeArchitecture(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                                 const StageControl &control)
{
    Architecture arch = Composer::run(nodes, launch, control);
    if (!arch.canceled)
        arch.diagnostics = ArchitectureChecks::run(arch, nodes, launch);
    return arch;
}

} // namespace rosarch
