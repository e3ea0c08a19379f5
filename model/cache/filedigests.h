#pragma once

#include <QByteArray>
#include <QHash>
#include <QMutex>
#include <QString>
#include <QStringList>

namespace rosarch {

/// The content digests (SHA-1) of files, memoised by what stat() says of them, so that a run
/// in which nothing changed learns it without reading or hashing a file. A file is read again
/// when its size, mtime (ns), ctime (ns), inode or device differ from the memo's. What this
/// cannot see: a rewrite that keeps the size and the inode and rewinds the mtime within the
/// ctime clock's granularity (ctime cannot be set back, short of moving the system clock), or
/// a file system that reports no real inode or ctime. A file changed within the last
/// `racyWindowNs` of being hashed is never memoised (like git's racily clean entries): a
/// second write in the same clock tick would keep every stat field.
/// Thread-safe.
class FileDigests
{
public:
    static constexpr qint64 kDefaultRacyWindowNs = 2'000'000'000;

    /// Digests memoised in `memoFile` ("" = not kept across runs).
    explicit FileDigests(const QString &memoFile = QString(),
                         qint64 racyWindowNs = kDefaultRacyWindowNs);
    FileDigests(const FileDigests &) = delete;
    FileDigests &operator=(const FileDigests &) = delete;

    /// The digest of the file at `absolutePath`; empty when it cannot be read.
    QByteArray digest(const QString &absolutePath);
    /// Each of `relativePaths` (below `root`) with its digest, as one byte string for a key;
    /// the files are looked at in parallel.
    QByteArray digestAll(const QString &root, const QStringList &relativePaths);
    /// The digest of bytes, as digest() gives it for a file holding them.
    static QByteArray digestOf(const QByteArray &content);

    /// Files hashed (read) since construction, for tests and benchmarks.
    int hashed() const;

    /// Whether the memo changed since it was last saved.
    bool changed() const;
    /// Writes the memo (a temporary file renamed) when anything changed; false on failure,
    /// with the reason in `error`. Digests go on meanwhile (the memo is written as it was).
    bool save(QString *error);

private:
    struct Stat
    {
        qint64 size = -1;
        qint64 mtimeNs = 0;
        qint64 ctimeNs = 0;
        quint64 inode = 0;
        quint64 device = 0;
        bool operator==(const Stat &) const = default;
    };
    struct Entry
    {
        Stat stat;
        QByteArray digest;
    };
    static bool statOf(const QString &path, Stat *out);
    void loadLocked();

    QString m_memoFile;
    qint64 m_racyWindowNs;
    mutable QMutex m_mutex;
    QHash<QString, Entry> m_entries;
    bool m_loaded = false;
    bool m_dirty = false;
    quint64 m_changes = 0; ///< changes to m_entries, so that save() knows what it wrote
    int m_hashed = 0;
};

} // namespace rosarch
