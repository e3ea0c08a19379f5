#pragma once

#include <QHash>
#include <QObject>
#include <QSet>
#include <QStringList>
#include <QTimer>

#include <optional>

class QFileSystemWatcher;

namespace rosarch {

/// Watches the open workspace's sources, build files and launch and parameter files, and asks
/// for a re-run of the stages a change affects once the changes settle (debounced): a launch,
/// YAML or parameter file alone re-runs stages 2-3, a source or build file all stages. The
/// tool's own files (rosarch.project.json, .rosarch*) and build output folders are ignored.
/// The number of watched paths is bounded: past the bound only folders are watched, which
/// still sees files added, removed or replaced (as editors save), not edits in place.
class WorkspaceWatcher : public QObject
{
    Q_OBJECT
public:
    enum class Rerun
    {
        Launch, ///< stages 2 and 3
        All,    ///< stages 1 to 3
    };
    Q_ENUM(Rerun)

    /// Paths watched at most (files and folders together).
    static constexpr int kMaxWatchedPaths = 8000;
    /// Quiet time after the last change before a re-run is asked for.
    static constexpr int kDebounceMs = 500;

    explicit WorkspaceWatcher(QObject *parent = nullptr);

    /// Watches `root` ("" stops watching).
    void setWorkspace(const QString &root);
    QString workspace() const { return m_root; }
    /// Off: nothing is watched and nothing asked for; on again: watches the workspace anew.
    void setEnabled(bool enabled);
    bool isEnabled() const { return m_enabled; }
    /// Whether files are watched one by one (false: the folders only, past the bound).
    bool watchesFiles() const { return m_watchesFiles; }
    /// Whether the watch is in place: the workspace is walked off the UI thread first, which
    /// takes a moment in a large one (`watching` follows).
    bool isWatching() const { return m_watcher != nullptr && m_unwatched.isEmpty(); }

    /// What a change of `relativePath` asks for; none for files the stages do not read.
    static std::optional<Rerun> rerunFor(const QString &relativePath);

Q_SIGNALS:
    /// The changes settled: re-run `rerun` for `files` (workspace-relative, sorted).
    void rerunRequested(rosarch::WorkspaceWatcher::Rerun rerun, const QStringList &files);
    /// The watch of the workspace is in place (watchesFiles() says how).
    void watching();

private:
    /// What to watch in a workspace: its folders, the files the stages read, and each
    /// folder's listing of those files.
    struct Walk
    {
        QStringList files;
        QStringList folders;
        QHash<QString, QHash<QString, qint64>> listings;
    };
    static Walk walk(const QString &root);
    static void watchFolder(const QString &root, const QString &folder, Walk *walk);
    static QHash<QString, qint64> listingOf(const QString &root, const QString &folder);

    void rebuild();
    void install(Walk walk);
    void addSome(int generation);
    void onFileChanged(const QString &path);
    void onFolderChanged(const QString &path);
    void note(const QString &absolutePath);
    void settle();
    QHash<QString, qint64> listing(const QString &folder) const;

    QFileSystemWatcher *m_watcher = nullptr;
    QTimer m_debounce;
    QString m_root;
    bool m_enabled = true;
    bool m_watchesFiles = true;
    QHash<QString, QHash<QString, qint64>> m_listings; ///< folder -> relevant file -> mtime
    QStringList m_unwatched; ///< paths still to add, a few per turn of the event loop
    int m_generation = 0;    ///< bumped by every rebuild; a walk of an older one is dropped
    QSet<QString> m_changed; ///< relative paths since the last ask
};

} // namespace rosarch
