#include "cache/filedigests.h"
#include "cache/sha1.h"

#include <QDataStream>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryFile>
#include <QThread>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentMap>

#include <sys/stat.h>
#include <time.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <functional>

namespace rosarch {

namespace {
constexpr quint32 kMagic = 0x52414644; // "RAFD"
constexpr quint32 kMemoVersion = 1;
constexpr qsizetype kHashSize = 20;
} // namespace

FileDigests::FileDigests(const QString &memoFile, qint64 racyWindowNs)
    : m_memoFile(memoFile), m_racyWindowNs(racyWindowNs)
{
}

bool FileDigests::statOf(const QString &path, Stat *out)
{
    struct stat st = {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0 || !S_ISREG(st.st_mode))
        return false;
    out->size = qint64(st.st_size);
    out->mtimeNs = qint64(st.st_mtim.tv_sec) * 1'000'000'000 + st.st_mtim.tv_nsec;
    out->ctimeNs = qint64(st.st_ctim.tv_sec) * 1'000'000'000 + st.st_ctim.tv_nsec;
    out->inode = quint64(st.st_ino);
    out->device = quint64(st.st_dev);
    return true;
}

QByteArray FileDigests::digestOf(const QByteArray &content)
{
    return Sha1::hash(content);
}

QByteArray FileDigests::digest(const QString &absolutePath)
{
    Stat before;
    if (!statOf(absolutePath, &before))
        return {};
    {
        QMutexLocker lock(&m_mutex);
        loadLocked();
        const auto it = m_entries.constFind(absolutePath);
        if (it != m_entries.constEnd() && it->stat == before)
            return it->digest;
    }
    QFile file(absolutePath);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QByteArray content = file.readAll();
    if (file.error() != QFileDevice::NoError)
        return {};
    const QByteArray digest = digestOf(content);
    Stat after;
    timespec clock = {};
    ::clock_gettime(CLOCK_REALTIME, &clock);
    const qint64 now = qint64(clock.tv_sec) * 1'000'000'000 + clock.tv_nsec;
    // Memoised only when the file did not change while it was read, and not just now.
    const bool steady = statOf(absolutePath, &after) && after == before &&
                        before.mtimeNs <= now - m_racyWindowNs &&
                        before.ctimeNs <= now - m_racyWindowNs;
    QMutexLocker lock(&m_mutex);
    ++m_hashed;
    if (steady) {
        m_entries.insert(absolutePath, {before, digest});
        m_dirty = true;
        ++m_changes;
    } else if (m_entries.remove(absolutePath) > 0) {
        m_dirty = true;
        ++m_changes;
    }
    return digest;
}

QByteArray FileDigests::digestAll(const QString &root, const QStringList &relativePaths)
{
    const std::function<QByteArray(const QString &)> one = [&](const QString &path) {
        return digest(root + QLatin1Char('/') + path);
    };
    QList<QByteArray> digests;
    if (QThreadPool::globalInstance()->contains(QThread::currentThread())) {
        // A task on the pool (the C++ macro index's key): waiting for the pool here would wait
        // behind the work that holds the pool's other threads, with this thread idle. The
        // digests are mostly memoised by then (the stage's key digested every file just before).
        digests.reserve(relativePaths.size());
        for (const QString &path : relativePaths)
            digests.append(one(path));
    } else {
        digests = QtConcurrent::blockingMapped<QList<QByteArray>>(relativePaths, one);
    }
    QByteArray out;
    out.reserve(relativePaths.size() * 80);
    for (qsizetype i = 0; i < relativePaths.size(); ++i)
        out += relativePaths.at(i).toUtf8() + '\0' + digests.at(i).toHex() + '\n';
    return out;
}

int FileDigests::hashed() const
{
    QMutexLocker lock(&m_mutex);
    return m_hashed;
}

void FileDigests::loadLocked()
{
    if (m_loaded)
        return;
    m_loaded = true;
    if (m_memoFile.isEmpty())
        return;
    QFile file(m_memoFile);
    if (!file.open(QIODevice::ReadOnly))
        return;
    const QByteArray bytes = file.readAll();
    // A damaged or foreign memo is no memo: every file is hashed again.
    if (bytes.size() < kHashSize || Sha1::hash(QByteArrayView(bytes).chopped(kHashSize)) !=
                                        QByteArrayView(bytes).last(kHashSize))
        return;
    QDataStream s(bytes.first(bytes.size() - kHashSize));
    s.setVersion(QDataStream::Qt_6_4);
    quint32 magic = 0, version = 0, count = 0;
    s >> magic >> version >> count;
    if (magic != kMagic || version != kMemoVersion)
        return;
    QHash<QString, Entry> entries;
    entries.reserve(qsizetype(qMin(count, 1u << 20)));
    for (quint32 i = 0; i < count && s.status() == QDataStream::Ok; ++i) {
        QString path;
        Entry e;
        s >> path >> e.stat.size >> e.stat.mtimeNs >> e.stat.ctimeNs >> e.stat.inode >>
            e.stat.device >> e.digest;
        entries.insert(path, e);
    }
    if (s.status() == QDataStream::Ok && s.atEnd())
        m_entries = std::move(entries);
}

bool FileDigests::changed() const
{
    QMutexLocker lock(&m_mutex);
    return m_dirty && !m_memoFile.isEmpty();
}

bool FileDigests::save(QString *error)
{
    QHash<QString, Entry> entries; // a copy (shared until changed): digests go on meanwhile
    quint64 changes = 0;
    {
        QMutexLocker lock(&m_mutex);
        if (!m_dirty || m_memoFile.isEmpty())
            return true;
        entries = m_entries;
        changes = m_changes;
    }
    QByteArray bytes;
    {
        QDataStream s(&bytes, QIODevice::WriteOnly);
        s.setVersion(QDataStream::Qt_6_4);
        s << kMagic << kMemoVersion << quint32(entries.size());
        for (auto it = entries.cbegin(); it != entries.cend(); ++it)
            s << it.key() << it->stat.size << it->stat.mtimeNs << it->stat.ctimeNs << it->stat.inode
              << it->stat.device << it->digest;
    }
    bytes += Sha1::hash(bytes);
    // Another process may save its memo at the same time: each writes its own temporary file
    // and the last rename wins, whole.
    QTemporaryFile file(m_memoFile + QStringLiteral(".XXXXXX"));
    file.setAutoRemove(false);
    const bool written = file.open() && file.write(bytes) == bytes.size() && file.flush();
    const QString temporary = file.fileName();
    const QString why = file.errorString();
    file.close();
    if (!written || std::rename(QFile::encodeName(temporary).constData(),
                                QFile::encodeName(m_memoFile).constData()) != 0) {
        if (!temporary.isEmpty())
            QFile::remove(temporary);
        if (error)
            *error = written ? QString::fromLocal8Bit(std::strerror(errno)) : why;
        return false;
    }
    QMutexLocker lock(&m_mutex);
    if (m_changes == changes) // else what changed meanwhile is saved next time
        m_dirty = false;
    return true;
}

} // namespace rosarch
