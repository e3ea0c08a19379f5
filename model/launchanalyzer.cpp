#include "launchanalyzer.h"

namespace rosarch {

LaunchDependencies LaunchAnalyzer::run(const Workspace &, const AtomicNodeList &, const LaunchOptions &,
                                       const StageControl &)
{
    return {};
}

} // namespace rosarch
