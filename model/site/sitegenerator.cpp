#include "site/sitegenerator.h"
#include "site/channelpage.h"
#include "site/findingspage.h"
#include "site/indexpage.h"
#include "site/launchpage.h"
#include "site/nodepage.h"
#include "site/sitemodel.h"
#include "site/systempage.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QSet>
#include <QThread>
#include <QtConcurrent/QtConcurrentMap>

#include <mutex>

// Resources of a static library must be registered explicitly; outside any namespace.
static void initSiteResources()
{
    static std::once_flag once;
    std::call_once(once, [] { Q_INIT_RESOURCE(site); });
}

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::SiteGenerator", text);
}

QByteArray resource(const QString &name)
{
    initSiteResources();
    QFile file(QStringLiteral(":/site/assets/") + name);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

QString SiteGenerator::manifestName()
{
    return QStringLiteral(".rosarch-site");
}

QList<SiteFile> SiteGenerator::files(const Recovery &recovery, const Project &project,
                                     const SiteOptions &options, const Progress &progress,
                                     bool *canceled)
{
    if (canceled)
        *canceled = false;
    const SiteModel model(recovery, project);
    SiteContext context;
    context.model = &model;
    context.title = options.title.isEmpty() ? QDir(options.workspace).dirName() : options.title;
    context.version = options.version;
    context.source =
        options.sourceUrl.isEmpty()
            ? SiteSource::relative(options.siteFolder, options.workspace)
            : SiteSource::pattern(options.sourceUrl, options.commit, options.repositoryPrefix);

    // Pages are written in a fixed order; each is a function of the model alone.
    QList<std::function<SiteFile()>> pages;
    pages << [&] { return IndexPage::index(context); };
    pages << [&] { return IndexPage::search(context); };
    pages << [&] { return FindingsPage::write(context); };
    for (const SiteSystem &s : model.systems())
        pages << [&context, &s] { return SystemPage::write(context, s); };
    for (const AtomicNode &n : model.recovery().nodes.nodes)
        pages << [&context, &n] { return NodePage::write(context, n); };
    for (auto it = model.channels().cbegin(); it != model.channels().cend(); ++it)
        pages << [&context, key = it.key(), &channel = *it] {
            return ChannelPage::write(context, key, channel);
        };
    for (const QString &f : model.recovery().launch.launchFiles)
        pages << [&context, &f] { return LaunchPage::write(context, f); };
    QStringList packageNames;
    for (const RosPackage &p : model.recovery().nodes.packages)
        if (!packageNames.contains(p.name)) {
            packageNames << p.name;
            pages << [&context, &p] { return IndexPage::package(context, p); };
        }

    QList<SiteFile> out;
    out << SiteFile{QStringLiteral("assets/site.css"), resource(QStringLiteral("site.css"))};
    out << SiteFile{QStringLiteral("assets/site.js"), resource(QStringLiteral("site.js"))};
    out << IndexPage::searchIndex(model);
    // Each page is a pure function of the model: they are made on the thread pool (the
    // layouts run in helper processes side by side), in their fixed order.
    const QFuture<SiteFile> made =
        QtConcurrent::mapped(pages, [](const std::function<SiteFile()> &page) { return page(); });
    const int total = int(pages.size());
    int reported = -1;
    while (!made.isFinished()) {
        const int done = made.progressValue();
        if (progress && done != reported) {
            reported = done;
            if (!progress(done, total)) {
                QFuture<SiteFile>(made).cancel();
                QFuture<SiteFile>(made).waitForFinished();
                if (canceled)
                    *canceled = true;
                return {};
            }
        }
        QThread::msleep(20);
    }
    if (progress)
        progress(total, total);
    out.append(made.results());
    std::sort(out.begin(), out.end(),
              [](const SiteFile &a, const SiteFile &b) { return a.path < b.path; });
    return out;
}

bool SiteGenerator::write(const QList<SiteFile> &files, const QString &folder, QString *error)
{
    const QDir dir(folder);
    const QString manifest = dir.filePath(manifestName());
    const QFileInfo info(folder);
    if (info.exists() && !info.isDir()) {
        *error = tr("%1 is a file, not a folder: choose a folder for the site.")
                     .arg(QDir::toNativeSeparators(folder));
        return false;
    }
    QStringList previous;
    if (info.exists()) {
        QFile list(manifest);
        if (list.open(QIODevice::ReadOnly)) {
            previous = QString::fromUtf8(list.readAll()).split(u'\n', Qt::SkipEmptyParts);
        } else if (!dir.isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden)) {
            *error = tr("%1 is not empty and holds no site rosarch wrote: choose an empty or "
                        "new folder, so that no file of yours is overwritten.")
                         .arg(QDir::toNativeSeparators(folder));
            return false;
        }
    }
    if (!QDir().mkpath(folder)) {
        *error = tr("Cannot create the folder %1: check that its parent exists and is "
                    "writable.")
                     .arg(QDir::toNativeSeparators(folder));
        return false;
    }
    QStringList written;
    QSet<QString> writtenSet;
    for (const SiteFile &f : files) {
        const QString path = dir.filePath(f.path);
        written << f.path;
        writtenSet.insert(f.path);
        QFile existing(path);
        if (existing.open(QIODevice::ReadOnly) && existing.size() == f.data.size() &&
            existing.readAll() == f.data)
            continue; // unchanged: keep the file as it is
        existing.close();
        if (!QDir().mkpath(QFileInfo(path).absolutePath())) {
            *error = tr("Cannot create the folder %1.")
                         .arg(QDir::toNativeSeparators(QFileInfo(path).absolutePath()));
            return false;
        }
        QSaveFile out(path);
        if (!out.open(QIODevice::WriteOnly) || out.write(f.data) != f.data.size() ||
            !out.commit()) {
            *error =
                tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(path), out.errorString());
            return false;
        }
    }
    for (const QString &old : std::as_const(previous))
        if (!writtenSet.contains(old) && !old.contains(QLatin1String("..")))
            QFile::remove(dir.filePath(old));
    QSaveFile list(manifest);
    const QByteArray text = written.join(u'\n').toUtf8() + '\n';
    if (!list.open(QIODevice::WriteOnly) || list.write(text) != text.size() || !list.commit()) {
        *error =
            tr("Cannot write %1: %2").arg(QDir::toNativeSeparators(manifest), list.errorString());
        return false;
    }
    return true;
}

} // namespace rosarch
