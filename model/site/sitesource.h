#pragma once

#include "core/evidence.h"

#include <QString>

namespace rosarch {

/// Where the site's source links point. By default, relative links from the site's folder to
/// the workspace's files (which are not copied: the links work beside a checkout of the
/// source). With a pattern (`https://github.com/org/repo/blob/{commit}/{path}#L{line}`),
/// `{path}` is the file relative to the repository root, `{line}` its line and `{commit}`
/// the repository's commit.
class SiteSource
{
public:
    SiteSource() = default;
    /// Relative links from `siteFolder` to the files of `workspace` (both folders on disk).
    static SiteSource relative(const QString &siteFolder, const QString &workspace);
    /// Links by `pattern`; `repositoryPrefix` is the workspace's folder inside its repository
    /// ("" at its root, else ending in "/").
    static SiteSource pattern(const QString &pattern, const QString &commit,
                              const QString &repositoryPrefix);

    /// The link to `evidence` from a page `depth` folders below the site's root ("" when the
    /// evidence names no file).
    QString url(const Evidence &evidence, int depth) const;
    /// Whether the pattern needs a commit (it holds {commit}).
    static bool needsCommit(const QString &pattern);

    /// What git says about the folder `workspace`: its HEAD commit and the folder's prefix in
    /// the repository. False when it is not in a git repository (or git is missing).
    static bool gitInfo(const QString &workspace, QString *commit, QString *prefix);

private:
    QString m_pattern; ///< "" = relative
    QString m_commit;
    QString m_prefix; ///< relative: from the site root to the workspace; else the repository's
};

} // namespace rosarch
