#pragma once

#include <QStringList>

namespace rosarch {

/// `rosarch export nodl <workspace> --out <dir>`: the recovered node classes (with the
/// workspace's project applied, as `recover` does) in another tool's format; today NoDL, one
/// document per class at <dir>/<package>/<executable>.nodl.json. Exit codes: 0 written,
/// 1 the analysis or the writing failed, 2 usage. `arguments` includes the program.
namespace ExportCommand {
int run(const QStringList &arguments);
}

} // namespace rosarch
