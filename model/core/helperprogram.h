#pragma once

#include <QString>

namespace rosarch {

/// Finds one of rosarch's helper programs (rosarch-layout, rosarch-stages): `configured` when
/// given, else the path in the environment variable `environment`, else `name` next to the
/// application, else `buildTree` (the build's own copy). "" when none is executable.
QString findHelperProgram(const QString &configured, const char *environment, const QString &name,
                          const QString &buildTree);

} // namespace rosarch
