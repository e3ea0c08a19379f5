#pragma once

#include "core/evidence.h"
#include "site/sitesource.h"

#include <QByteArray>
#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

namespace rosarch {

class SiteModel;

/// One file of the site: its path below the site's root and its bytes.
struct SiteFile
{
    QString path;
    QByteArray data;
};

/// What every page is written with: the model, the site's title and where source links go.
struct SiteContext
{
    const SiteModel *model = nullptr;
    QString title;
    SiteSource source;
    QString version; ///< rosarch's, in the footer
};

/// The HTML the pages share: escaping, links between pages (relative, so that the site works
/// from a folder, a file:// URL or any web server), source links and the page frame.
namespace SiteHtml {
QString escape(const QString &text);
/// The link from the page at `from` to the page at `to` (both site-relative paths).
QString href(const QString &from, const QString &to);
/// `<a href>text</a>` from `from` to `to`; the text alone when `to` is "".
QString link(const QString &from, const QString &to, const QString &text);
/// A link to the source line of `evidence` ("" when it names no file).
QString source(const SiteContext &context, const QString &from, const Evidence &evidence);
/// `<code>` around escaped text.
QString code(const QString &text);
/// A table: header cells, then rows of ready HTML cells; `caption` for screen readers.
QString table(const QString &caption, const QStringList &headers, const QList<QStringList> &rows,
              const QString &cssClass = {});
/// The whole page: head, header with navigation and search, breadcrumbs (label, path; the
/// last is this page), `<main>` with the `<h1>` and `body`, footer.
SiteFile page(const SiteContext &context, const QString &path, const QString &title,
              const QList<QPair<QString, QString>> &crumbs, const QString &body);
} // namespace SiteHtml

} // namespace rosarch
