#pragma once

#include "pipeline/recovery.h"
#include "project/project.h"
#include "site/sitehtml.h"

#include <QList>
#include <QString>

#include <functional>

namespace rosarch {

/// What a site is written with.
struct SiteOptions
{
    QString title;      ///< the site's name ("" = the workspace folder's name)
    QString workspace;  ///< the workspace folder (for relative source links)
    QString siteFolder; ///< where the site goes (relative source links start there)
    /// Source links by pattern with {path}, {line} and {commit} ("" = relative links).
    QString sourceUrl;
    QString commit;           ///< fills {commit}
    QString repositoryPrefix; ///< the workspace's folder in its repository ("" or "a/b/")
    QString version;          ///< rosarch's, in the footer
};

/// The architecture site of an accepted model (issue: a newcomer reads it in a browser):
/// index, a page per system, node class, topic, service, action, launch file and package,
/// the findings, the search page and index, a stylesheet and a script. The same model and
/// options give byte-identical files: everything is sorted, nothing is dated.
class SiteGenerator
{
public:
    /// Called after each page with the pages done and the total; returning false cancels.
    using Progress = std::function<bool(int done, int total)>;

    /// Every file of the site; empty (and `canceled` true) when `progress` canceled.
    static QList<SiteFile> files(const Recovery &recovery, const Project &project,
                                 const SiteOptions &options, const Progress &progress = {},
                                 bool *canceled = nullptr);

    /// Writes the site into `folder`, which must be empty, missing, or a site written before
    /// (its files that the new site no longer has are removed; files it did not write are left
    /// alone). False with a message that says what to do when it cannot.
    static bool write(const QList<SiteFile> &files, const QString &folder, QString *error);

    /// The name of the list of written files kept in the site's folder.
    static QString manifestName();
};

} // namespace rosarch
