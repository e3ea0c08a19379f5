#pragma once

#include <QStringList>

namespace rosarch {

/// `rosarch site <workspace> --out <dir> [--title T] [--source-url PATTERN]`: the architecture
/// site of the accepted model (the workspace's project applied, as `recover` applies it),
/// static HTML a newcomer reads in a browser. Exit codes: 0 written, 1 the analysis or the
/// writing failed (or found nothing to show), 2 usage. `arguments` includes the program.
namespace SiteCommand {
int run(const QStringList &arguments);
}

} // namespace rosarch
