#include "analysiscache.h"

#include <QCryptographicHash>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QStandardPaths>
#include <QTemporaryFile>
#include <QtEndian>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <vector>

namespace rosarch {

namespace {

constexpr char kMagic[4] = {'R', 'A', 'C', 'E'};
constexpr qsizetype kHashSize = 20; // SHA-1
constexpr qsizetype kHeaderSize = 4 + 4 + kHashSize;

QByteArray checksum(QByteArrayView bytes)
{
    return QCryptographicHash::hash(bytes, QCryptographicHash::Sha1);
}

QByteArray header(const QByteArray &key)
{
    QByteArray h(kMagic, 4);
    const quint32 format = qToBigEndian(quint32(AnalysisCache::kFormatVersion));
    h.append(reinterpret_cast<const char *>(&format), 4);
    h.append(key);
    return h;
}

} // namespace

AnalysisCache::AnalysisCache(const QString &root, qint64 maxBytes)
    : m_root(root.isEmpty() ? QString() : root + QStringLiteral("/analysis")), m_maxBytes(maxBytes)
{
    if (root.isEmpty())
        return;
    m_directory =
        m_root + QStringLiteral("/%1-f%2").arg(QStringLiteral(ROSARCH_VERSION)).arg(kFormatVersion);
    if (!QDir().mkpath(m_directory) || !QFileInfo(m_directory).isWritable()) {
        m_problem = QStringLiteral("The analysis cache folder %1 cannot be created or written; "
                                   "this run analyses every file without the cache.")
                        .arg(m_directory);
        return;
    }
    m_enabled = true;
}

AnalysisCache &AnalysisCache::shared()
{
    static AnalysisCache cache(defaultRoot());
    return cache;
}

QString AnalysisCache::defaultRoot()
{
    if (qEnvironmentVariableIntValue("ROSARCH_NO_CACHE") != 0)
        return {};
    const QString configured = qEnvironmentVariable("ROSARCH_CACHE_DIR");
    if (!configured.isEmpty())
        return configured;
    const QString generic = QStandardPaths::writableLocation(QStandardPaths::GenericCacheLocation);
    return generic.isEmpty() ? QString() : generic + QStringLiteral("/rosarch");
}

QByteArray AnalysisCache::key(std::initializer_list<QByteArrayView> parts)
{
    QCryptographicHash hash(QCryptographicHash::Sha1);
    for (QByteArrayView part : parts) {
        // Each part with its length, so that ("ab", "c") and ("a", "bc") differ.
        const quint64 size = qToBigEndian(quint64(part.size()));
        hash.addData(QByteArrayView(reinterpret_cast<const char *>(&size), sizeof size));
        hash.addData(part);
    }
    return hash.result();
}

QString AnalysisCache::entryPath(const QString &kind, const QByteArray &key) const
{
    const QString hex = QString::fromLatin1(key.toHex());
    return m_directory + QLatin1Char('/') + kind + QLatin1Char('/') + hex.left(2) +
           QLatin1Char('/') + hex;
}

std::optional<QByteArray> AnalysisCache::load(const QString &kind, const QByteArray &key)
{
    if (!m_enabled)
        return std::nullopt;
    QFile file(entryPath(kind, key));
    if (!file.open(QIODevice::ReadOnly)) {
        ++m_misses;
        return std::nullopt;
    }
    const QByteArray bytes = file.readAll();
    const QByteArray expected = header(key);
    const bool whole =
        bytes.size() >= kHeaderSize + kHashSize && bytes.startsWith(expected) &&
        checksum(QByteArrayView(bytes).chopped(kHashSize)) == QByteArrayView(bytes).last(kHashSize);
    if (!whole) {
        ++m_rejected;
        ++m_misses;
        return std::nullopt;
    }
    ++m_hits;
    return bytes.mid(kHeaderSize, bytes.size() - kHeaderSize - kHashSize);
}

void AnalysisCache::store(const QString &kind, const QByteArray &key, const QByteArray &payload)
{
    if (!m_enabled)
        return;
    const QString path = entryPath(kind, key);
    if (!QDir().mkpath(QFileInfo(path).path())) {
        fail(QStringLiteral("The analysis cache folder %1 cannot be created")
                 .arg(QFileInfo(path).path()));
        return;
    }
    QByteArray bytes = header(key) + payload;
    bytes += checksum(bytes);
    // A temporary file renamed over the entry: readers see the old entry or the whole new one.
    // Not synced to disk (QSaveFile would, thousands of times in a cold run): an entry a crash
    // leaves incomplete fails its checksum and is analysed again.
    QTemporaryFile file(path + QStringLiteral(".XXXXXX"));
    file.setAutoRemove(false);
    const bool written = file.open() && file.write(bytes) == bytes.size() && file.flush();
    const QString temporary = file.fileName();
    const QString error = file.errorString();
    file.close();
    if (!written || std::rename(QFile::encodeName(temporary).constData(),
                                QFile::encodeName(path).constData()) != 0) {
        QFile::remove(temporary);
        fail(QStringLiteral("An entry of the analysis cache could not be written to %1 (%2)")
                 .arg(path, written ? QString::fromLocal8Bit(std::strerror(errno)) : error));
        return;
    }
    ++m_stores;
    m_storedSinceTrim = true;
}

void AnalysisCache::fail(const QString &why)
{
    m_enabled = false;
    QMutexLocker lock(&m_mutex);
    if (m_problem.isEmpty())
        m_problem = why + QStringLiteral("; the cache is off for the rest of this run.");
}

AnalysisCache::Statistics AnalysisCache::statistics() const
{
    return {m_hits.load(), m_misses.load(), m_rejected.load(), m_stores.load()};
}

std::optional<Diagnostic> AnalysisCache::takeProblem()
{
    QMutexLocker lock(&m_mutex);
    if (m_problem.isEmpty() || m_problemTaken)
        return std::nullopt;
    m_problemTaken = true;
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("cache-unavailable");
    d.message = m_problem;
    return d;
}

void AnalysisCache::trim()
{
    if (!m_enabled || !m_storedSinceTrim.exchange(false))
        return;
    struct Entry
    {
        qint64 modified;
        qint64 size;
        QString path;
    };
    std::vector<Entry> entries;
    qint64 total = 0;
    QDirIterator it(m_root, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        it.next();
        const QFileInfo info = it.fileInfo();
        entries.push_back({info.lastModified().toMSecsSinceEpoch(), info.size(), info.filePath()});
        total += info.size();
    }
    if (total <= m_maxBytes)
        return;
    std::sort(entries.begin(), entries.end(), [](const Entry &a, const Entry &b) {
        return a.modified < b.modified || (a.modified == b.modified && a.path < b.path);
    });
    const qint64 goal = m_maxBytes - m_maxBytes / 10; // room for the next runs
    for (const Entry &e : entries) {
        if (total <= goal)
            break;
        if (QFile::remove(e.path))
            total -= e.size;
    }
}

} // namespace rosarch
