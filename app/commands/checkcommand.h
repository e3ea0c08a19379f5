#pragma once

#include <QStringList>

namespace rosarch {

/// `rosarch check <workspace> [--format text|json|sarif|junit] [--output f] [--baseline f]
/// [--write-baseline f] [--fail-on error|warning|info|never]`: the diagnostics and the
/// architecture checks of a recovery, for CI. Exit codes (CheckExit): 0 nothing new at or above
/// --fail-on, 1 new findings at or above it, 2 usage, 3 a file could not be read or written.
/// `arguments` includes the program.
int runCheck(const QStringList &arguments);

enum CheckExit
{
    CheckPassed = 0,
    CheckFailed = 1,
    CheckUsage = 2,
    CheckIoError = 3
};

} // namespace rosarch
