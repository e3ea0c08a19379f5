#include "app/workspacewatcher.h"
#include "jobs/stallprobe.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QFutureWatcher>
#include <QTimer>
#include <QtConcurrent>

#include <algorithm>

namespace rosarch {

namespace {

bool isSkippedFolder(const QString &name)
{
    // As the workspace scanner: build output, hidden folders and caches are not read.
    return name.startsWith(QLatin1Char('.')) || name == QLatin1String("build") ||
           name == QLatin1String("install") || name == QLatin1String("log") ||
           name == QLatin1String("node_modules") || name == QLatin1String("__pycache__");
}

bool isLaunchName(const QString &name)
{
    return name.endsWith(QLatin1String(".launch.py")) ||
           name.endsWith(QLatin1String("_launch.py")) ||
           name.endsWith(QLatin1String(".launch.xml")) ||
           name.endsWith(QLatin1String(".launch.yaml")) || name.endsWith(QLatin1String(".launch"));
}

} // namespace

WorkspaceWatcher::WorkspaceWatcher(QObject *parent) : QObject(parent)
{
    m_debounce.setSingleShot(true);
    m_debounce.setInterval(kDebounceMs);
    connect(&m_debounce, &QTimer::timeout, this, &WorkspaceWatcher::settle);
}

std::optional<WorkspaceWatcher::Rerun> WorkspaceWatcher::rerunFor(const QString &relativePath)
{
    const QStringList parts = relativePath.split(QLatin1Char('/'), Qt::SkipEmptyParts);
    if (parts.isEmpty())
        return std::nullopt;
    for (qsizetype i = 0; i + 1 < parts.size(); ++i)
        if (isSkippedFolder(parts.at(i)))
            return std::nullopt;
    const QString &name = parts.last();
    // The tool's own files: the project, its autosave and anything else it keeps there.
    if (name == QLatin1String("rosarch.project.json") || name.startsWith(QLatin1String(".rosarch")))
        return std::nullopt;
    if (name == QLatin1String("package.xml") || name == QLatin1String("setup.py") ||
        name == QLatin1String("setup.cfg") || name == QLatin1String("CMakeLists.txt"))
        return Rerun::All;
    const QString suffix = QFileInfo(name).suffix().toLower();
    if (isLaunchName(name) || suffix == QLatin1String("xml") || suffix == QLatin1String("yaml") ||
        suffix == QLatin1String("yml"))
        return Rerun::Launch;
    static const QSet<QString> sources{
        QStringLiteral("py"),  QStringLiteral("cpp"), QStringLiteral("cc"),
        QStringLiteral("cxx"), QStringLiteral("hpp"), QStringLiteral("h"),
        QStringLiteral("hh"),  QStringLiteral("hxx"), QStringLiteral("ipp")};
    if (sources.contains(suffix))
        return Rerun::All;
    return std::nullopt;
}

void WorkspaceWatcher::setWorkspace(const QString &root)
{
    m_root = root.isEmpty() ? QString() : QFileInfo(root).absoluteFilePath();
    rebuild();
}

void WorkspaceWatcher::setEnabled(bool enabled)
{
    if (enabled == m_enabled)
        return;
    m_enabled = enabled;
    rebuild();
}

QHash<QString, qint64> WorkspaceWatcher::listingOf(const QString &root, const QString &folder)
{
    QHash<QString, qint64> out;
    const QFileInfoList entries = QDir(folder).entryInfoList(QDir::Files | QDir::Hidden);
    for (const QFileInfo &e : entries)
        if (rerunFor(QDir(root).relativeFilePath(e.absoluteFilePath())))
            out.insert(e.fileName(), e.lastModified().toMSecsSinceEpoch());
    return out;
}

QHash<QString, qint64> WorkspaceWatcher::listing(const QString &folder) const
{
    return listingOf(m_root, folder);
}

void WorkspaceWatcher::watchFolder(const QString &root, const QString &folder, Walk *walk)
{
    walk->folders.append(folder);
    const QFileInfoList entries = QDir(folder).entryInfoList(
        QDir::Dirs | QDir::Files | QDir::NoDotAndDotDot | QDir::Hidden, QDir::Name);
    for (const QFileInfo &e : entries) {
        if (e.isDir()) {
            if (!e.isSymLink() && !isSkippedFolder(e.fileName()) &&
                walk->folders.size() + walk->files.size() < kMaxWatchedPaths * 4)
                watchFolder(root, e.absoluteFilePath(), walk);
        } else if (rerunFor(QDir(root).relativeFilePath(e.absoluteFilePath()))) {
            walk->files.append(e.absoluteFilePath());
        }
    }
}

WorkspaceWatcher::Walk WorkspaceWatcher::walk(const QString &root)
{
    Walk w;
    watchFolder(root, root, &w);
    if (w.folders.size() > kMaxWatchedPaths)
        w.folders = w.folders.mid(0, kMaxWatchedPaths); // the outer folders, found first
    for (const QString &folder : std::as_const(w.folders))
        w.listings.insert(folder, listingOf(root, folder));
    return w;
}

void WorkspaceWatcher::rebuild()
{
    ++m_generation;
    delete m_watcher;
    m_watcher = nullptr;
    m_unwatched.clear();
    m_listings.clear();
    m_changed.clear();
    m_debounce.stop();
    if (!m_enabled || m_root.isEmpty() || !QFileInfo(m_root).isDir())
        return;
    // Walking a large workspace (every folder listed) takes long enough to stall the window:
    // it runs off the UI thread, and the watch is put in place when it is done.
    const int generation = m_generation;
    auto *done = new QFutureWatcher<Walk>(this);
    connect(done, &QFutureWatcherBase::finished, this, [this, done, generation] {
        done->deleteLater();
        if (generation == m_generation)
            install(done->result());
    });
    done->setFuture(QtConcurrent::run(&WorkspaceWatcher::walk, m_root));
}

void WorkspaceWatcher::install(Walk walk)
{
    m_watcher = new QFileSystemWatcher(this);
    connect(m_watcher, &QFileSystemWatcher::fileChanged, this, &WorkspaceWatcher::onFileChanged);
    connect(m_watcher, &QFileSystemWatcher::directoryChanged, this,
            &WorkspaceWatcher::onFolderChanged);
    m_watchesFiles = walk.folders.size() + walk.files.size() <= kMaxWatchedPaths;
    m_unwatched = walk.folders;
    if (m_watchesFiles)
        m_unwatched += walk.files;
    m_listings = std::move(walk.listings);
    addSome(m_generation);
}

// Each path costs a system call on the UI thread (thousands in a large workspace): a few
// hundred per turn of the event loop, so that the window keeps answering meanwhile.
void WorkspaceWatcher::addSome(int generation)
{
    if (generation != m_generation || !m_watcher)
        return;
    const StallScope scope("WorkspaceWatcher adds paths");
    constexpr qsizetype kPerTurn = 400;
    m_watcher->addPaths(m_unwatched.mid(0, kPerTurn));
    m_unwatched.remove(0, std::min(kPerTurn, m_unwatched.size()));
    if (!m_unwatched.isEmpty()) {
        QTimer::singleShot(0, this, [this, generation] { addSome(generation); });
        return;
    }
    Q_EMIT watching();
}

void WorkspaceWatcher::note(const QString &absolutePath)
{
    const QString relative = QDir(m_root).relativeFilePath(absolutePath);
    if (!rerunFor(relative))
        return;
    m_changed.insert(relative);
    m_debounce.start(); // again: a burst of saves is one re-run
}

void WorkspaceWatcher::onFileChanged(const QString &path)
{
    note(path);
    // A file replaced by a rename (as many editors save) is no longer watched: watch it again.
    if (m_watcher && m_watchesFiles && QFileInfo::exists(path) &&
        !m_watcher->files().contains(path))
        m_watcher->addPath(path);
}

void WorkspaceWatcher::onFolderChanged(const QString &path)
{
    // What changed in the folder: files added, removed, or replaced with a new time.
    const QHash<QString, qint64> before = m_listings.value(path);
    const QHash<QString, qint64> after = listing(path);
    for (auto it = after.cbegin(); it != after.cend(); ++it) {
        if (before.value(it.key(), -1) != it.value()) {
            const QString file = QDir(path).filePath(it.key());
            note(file);
            if (m_watcher && m_watchesFiles && !m_watcher->files().contains(file))
                m_watcher->addPath(file);
        }
    }
    for (auto it = before.cbegin(); it != before.cend(); ++it)
        if (!after.contains(it.key()))
            note(QDir(path).filePath(it.key()));
    m_listings.insert(path, after);
    // A new sub-folder (a new package, say) is watched too.
    const QFileInfoList subfolders =
        QDir(path).entryInfoList(QDir::Dirs | QDir::NoDotAndDotDot | QDir::Hidden);
    for (const QFileInfo &d : subfolders) {
        if (!m_watcher || isSkippedFolder(d.fileName()) ||
            m_listings.contains(d.absoluteFilePath()) ||
            m_watcher->directories().size() >= kMaxWatchedPaths)
            continue;
        m_watcher->addPath(d.absoluteFilePath());
        m_listings.insert(d.absoluteFilePath(), listing(d.absoluteFilePath()));
        for (const QString &name : m_listings.value(d.absoluteFilePath()).keys())
            note(QDir(d.absoluteFilePath()).filePath(name));
    }
}

void WorkspaceWatcher::settle()
{
    if (m_changed.isEmpty())
        return;
    QStringList files(m_changed.cbegin(), m_changed.cend());
    files.sort();
    m_changed.clear();
    Rerun rerun = Rerun::Launch;
    for (const QString &f : std::as_const(files))
        if (rerunFor(f) == Rerun::All)
            rerun = Rerun::All;
    Q_EMIT rerunRequested(rerun, files);
}

} // namespace rosarch
