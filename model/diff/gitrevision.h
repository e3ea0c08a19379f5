#pragma once

#include <QByteArray>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A workspace as it was at a git revision, for comparing recoveries.
namespace GitRevision {
/// Runs git with `arguments` in `folder`, waiting at most `timeoutMs` for it to finish: its
/// standard output in `output` (when given), or false with git's own message in `error`
/// (when given) when git cannot start, fails or runs out of time.
bool run(const QString &folder, const QStringList &arguments, QByteArray *output,
         QString *error = nullptr, int timeoutMs = 300000);

/// Writes the tree of `workspace` (a git work tree, or a folder inside one) at `revision` into
/// the empty folder `into` (git archive "rev:path", unpacked with tar), so that `into` is the
/// workspace at that revision. False, with git's own message, when git or the revision fails.
bool checkout(const QString &workspace, const QString &revision, const QString &into,
              QString *error);
} // namespace GitRevision

} // namespace rosarch
