#pragma once

#include <QString>

namespace rosarch {

/// Finds one of rosarch's helper programs (rosarch-layout, rosarch-stages): `configured` when
/// given, else the path in the environment variable `environment`, else `name` next to the
/// application (the build tree keeps every executable in one folder), else `name` in the
/// installed helper folder relative to the application (libexec/rosarch). "" when none is
/// executable.
QString findHelperProgram(const QString &configured, const char *environment, const QString &name);

/// `relative` below rosarch's installed data folder (share/rosarch), found relative to the
/// application; "" when it does not exist there (as in the build tree).
QString findInstalledData(const QString &relative);

} // namespace rosarch
