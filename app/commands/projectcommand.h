#pragma once

#include "project/correctedmodel.h"

#include <QStringList>

namespace rosarch {

/// `rosarch project check <project file> <workspace>`: recovers the workspace, applies the
/// project and lists every decision and correction that matches nothing any more (blueprint
/// §5), for CI. Exit codes: 0 none orphaned, 1 some orphaned, 2 usage, 3 the project cannot be
/// read.
namespace ProjectCommand {
int run(const QStringList &arguments);
/// One line about `orphan` of the project `file`: "<file>: warning: correction c3 (rename)
/// matches nothing: ... (it said: ...)".
QString describe(const Orphan &orphan, const QString &file);
} // namespace ProjectCommand

} // namespace rosarch
