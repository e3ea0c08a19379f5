#pragma once

#include <QStringList>

namespace rosarch {

/// `rosarch eval --reference <dir|file> --recovered <dir|file> [--level acd|ccd] [--json]`:
/// scores a recovered PlantUML model against a reference one (blueprint §4) and prints the
/// table (or JSON). `arguments` includes the program name. Exit codes: 0 ok, 1 some input
/// diagram could not be read as an ACD or a CCD, 2 usage (missing options, unreadable paths).
int runEval(const QStringList &arguments);

} // namespace rosarch
