#pragma once

#include <QString>

namespace rosarch {

/// -1, 0 or 1 as package version `a` (package.xml's `<version>`) is older than, the same as or
/// newer than `b`, comparing the dot-separated numbers (a missing or non-numeric part counts
/// as 0).
int compareVersions(const QString &a, const QString &b);

} // namespace rosarch
