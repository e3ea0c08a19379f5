#pragma once

#include "core/atomicnodelist.h"
#include "core/diagnostic.h"
#include "core/launchdependencies.h"

#include <QList>

namespace rosarch {

/// The parameter checks of the judged systems (blueprint §1, docs/checks.md), each comparing
/// what a node instance is given with what its class and plugins declare:
/// - `parameter-undeclared`: a value, from the launch file or a parameter file, for a name
///   nothing declares (ROS 2 ignores it), with a did-you-mean from the declared names;
/// - `parameter-type`: a value of another type than the declared one;
/// - `parameter-range`: a number outside the range its descriptor allows;
/// - `parameter-missing`: a parameter declared without a default that nothing sets.
/// A class whose declarations the analysis cannot see whole (it takes any parameter, declares
/// none, derives from a class outside the workspace) is not judged, nor is a value for a plugin
/// outside the workspace, a value given to many nodes by a wildcard key, or a missing value of
/// an instance whose parameter files are not all read.
class ParameterChecks
{
public:
    static void run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                    QList<Diagnostic> *out);
};

} // namespace rosarch
