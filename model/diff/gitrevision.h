#pragma once

#include <QString>

namespace rosarch {

/// A workspace as it was at a git revision, for comparing recoveries.
namespace GitRevision {
/// Writes the tree of `workspace` (a git work tree, or a folder inside one) at `revision` into
/// the empty folder `into` (git archive "rev:path", unpacked with tar), so that `into` is the
/// workspace at that revision. False, with git's own message, when git or the revision fails.
bool checkout(const QString &workspace, const QString &revision, const QString &into,
              QString *error);
} // namespace GitRevision

} // namespace rosarch
