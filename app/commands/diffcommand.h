#pragma once

#include <QStringList>

namespace rosarch {

/// `rosarch diff <before> <after> [--format text|json] [--output f]`, where each side is an
/// artifact folder `rosarch recover` wrote or a workspace to recover; or `rosarch diff
/// <workspace> --rev A --rev B` for two git revisions of one workspace. Exit codes: 0 no
/// change, 1 changes, 2 usage, 3 an input could not be read (or git failed).
int runDiff(const QStringList &arguments);

} // namespace rosarch
