#include "cache/analysiscache.h"
#include "analysisfingerprint.h"
#include "cache/sha1.h"
#include "core/stagecontrol.h"
#include "core/threadpriority.h"

#include <QCoreApplication>
#include <QDataStream>
#include <QDateTime>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>
#include <QStandardPaths>
#include <QTemporaryFile>
#include <QtEndian>

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rosarch {

// A pack: "RACP", the format (u32), the payloads one after another, the index (QDataStream:
// count, then id, offset, length, checksum of each payload), and a footer: the index's offset
// (u64), its SHA-1, "RACX". Written whole by one process under a name of its own.
struct AnalysisCache::Pack
{
    QString path;
    QFile file;
};

namespace {

constexpr char kMagic[4] = {'R', 'A', 'C', 'P'};
constexpr char kFooterMagic[4] = {'R', 'A', 'C', 'X'};
constexpr qsizetype kHashSize = 20; // SHA-1
constexpr qsizetype kHeaderSize = 8;
constexpr qsizetype kFooterSize = 8 + kHashSize + 4;
constexpr quint32 kMaxIndexEntries = 1u << 22;

QByteArray checksum(QByteArrayView bytes)
{
    return Sha1::hash(bytes);
}

/// An entry's checksum: it guards against damage, not against forgery (the index that holds it
/// has a SHA-1), so it is a fast one. Two 64-bit lanes over 8-byte words, multiply-mixed; a
/// warm run checks megabytes of entries, which SHA-1 took ~10 ms for on nav2.
QByteArray entryChecksum(QByteArrayView bytes)
{
    constexpr quint64 kA = 0x9e3779b97f4a7c15ull, kB = 0xc2b2ae3d27d4eb4full;
    quint64 a = kA ^ quint64(bytes.size()), b = kB + quint64(bytes.size());
    const auto mix = [](quint64 h, quint64 w, quint64 k) {
        h ^= w * k;
        h = (h << 31) | (h >> 33);
        return h * 0xff51afd7ed558ccdull;
    };
    const char *p = bytes.data();
    qsizetype left = bytes.size();
    for (; left >= 16; p += 16, left -= 16) {
        a = mix(a, qFromLittleEndian<quint64>(p), kB);
        b = mix(b, qFromLittleEndian<quint64>(p + 8), kA);
    }
    char tail[16] = {};
    std::memcpy(tail, p, size_t(left));
    a = mix(a, qFromLittleEndian<quint64>(tail), kB);
    b = mix(b, qFromLittleEndian<quint64>(tail + 8), kA);
    a ^= b >> 29;
    b ^= a >> 31;
    const quint64 out[2] = {qToBigEndian(mix(a, b, kA)), qToBigEndian(mix(b, a, kB))};
    return QByteArray(reinterpret_cast<const char *>(out), sizeof out);
}

QByteArray readAt(QFile &file, qint64 offset, qint64 length)
{
    QByteArray bytes(length, Qt::Uninitialized);
    qint64 done = 0;
    while (done < length) {
        const ssize_t n = ::pread(file.handle(), bytes.data() + done, size_t(length - done),
                                  off_t(offset + done));
        if (n <= 0) {
            if (n < 0 && errno == EINTR)
                continue;
            return {};
        }
        done += n;
    }
    return bytes;
}

QString packName()
{
    // In the order written (by name, then by the files' times): the time, the process, a
    // counter, and a random part in case another process reuses the id.
    static std::atomic<int> counter{0};
    return QStringLiteral("%1-%2-%3-%4.pack")
        .arg(QDateTime::currentMSecsSinceEpoch(), 13, 10, QLatin1Char('0'))
        .arg(QCoreApplication::applicationPid())
        .arg(++counter, 6, 10, QLatin1Char('0'))
        .arg(QRandomGenerator::global()->generate(), 8, 16, QLatin1Char('0'));
}

} // namespace

AnalysisCache::AnalysisCache(const QString &root, qint64 maxBytes, qint64 racyWindowNs)
    : m_root(root.isEmpty() ? QString() : root + QStringLiteral("/analysis")), m_maxBytes(maxBytes)
{
    if (root.isEmpty()) {
        m_digests = std::make_unique<FileDigests>();
        return;
    }
    // The version, the analysis code's fingerprint and the format: a build whose analysis
    // differs never reads another's entries, even at the same version number.
    m_directory = m_root + QStringLiteral("/%1-%2-f%3")
                               .arg(QStringLiteral(ROSARCH_VERSION),
                                    QStringLiteral(ROSARCH_ANALYSIS_FINGERPRINT))
                               .arg(kFormatVersion);
    if (!QDir().mkpath(m_directory) || !QFileInfo(m_directory).isWritable()) {
        m_digests = std::make_unique<FileDigests>();
        m_problem = QStringLiteral("The analysis cache folder %1 cannot be created or written; "
                                   "this run analyses every file without the cache.")
                        .arg(m_directory);
        return;
    }
    m_digests =
        std::make_unique<FileDigests>(m_directory + QStringLiteral("/digests"), racyWindowNs);
    m_enabled = true;
}

AnalysisCache::~AnalysisCache()
{
    waitForWrites();
    flushDeferred();
    waitForWrites();
}

AnalysisCache &AnalysisCache::shared()
{
    static AnalysisCache cache(defaultRoot(), defaultMaxBytes());
    return cache;
}

AnalysisCache &AnalysisCache::of(const StageControl &control)
{
    if (auto *given = dynamic_cast<AnalysisCache *>(control.cache))
        return *given;
    // Off: a stage given no cache looks nothing up and stores nothing, whoever calls it.
    static AnalysisCache off{QString()};
    return off;
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

qint64 AnalysisCache::defaultMaxBytes()
{
    bool ok = false;
    const qint64 mb = qEnvironmentVariable("ROSARCH_CACHE_MAX_MB").toLongLong(&ok);
    return ok && mb > 0 ? mb * 1024 * 1024 : kDefaultMaxBytes;
}

QByteArray AnalysisCache::key(std::initializer_list<QByteArrayView> parts)
{
    Sha1 hash;
    for (QByteArrayView part : parts) {
        // Each part with its length, so that ("ab", "c") and ("a", "bc") differ.
        const quint64 size = qToBigEndian(quint64(part.size()));
        hash.addData(QByteArrayView(reinterpret_cast<const char *>(&size), sizeof size));
        hash.addData(part);
    }
    return hash.result();
}

QByteArray AnalysisCache::entryId(const QString &kind, const QByteArray &key)
{
    return kind.toLatin1() + '\0' + key;
}

void AnalysisCache::rejectPack(const QString &path)
{
    // Counted once: the folder is read again after each flush.
    if (!m_rejectedPacks.contains(path)) {
        m_rejectedPacks.insert(path);
        ++m_rejected;
    }
}

void AnalysisCache::openPacks()
{
    if (m_opened)
        return;
    m_opened = true;
    QStringList names =
        QDir(m_directory).entryList({QStringLiteral("*.pack")}, QDir::Files, QDir::Name);
    for (const QString &name : std::as_const(names)) { // oldest first: newer entries win
        auto pack = std::make_shared<Pack>();
        pack->path = m_directory + QLatin1Char('/') + name;
        pack->file.setFileName(pack->path);
        if (!pack->file.open(QIODevice::ReadOnly))
            continue; // removed by another process meanwhile
        const qint64 size = pack->file.size();
        const QByteArray header = readAt(pack->file, 0, kHeaderSize);
        const QByteArray footer = readAt(pack->file, size - kFooterSize, kFooterSize);
        QByteArray expected(kMagic, 4);
        const quint32 format = qToBigEndian(quint32(kFormatVersion));
        expected.append(reinterpret_cast<const char *>(&format), 4);
        if (size < kHeaderSize + kFooterSize || header != expected ||
            !footer.endsWith(QByteArrayView(kFooterMagic, 4))) {
            rejectPack(pack->path);
            continue;
        }
        const qint64 indexAt = qFromBigEndian<qint64>(footer.constData());
        if (indexAt < kHeaderSize || indexAt > size - kFooterSize) {
            rejectPack(pack->path);
            continue;
        }
        const QByteArray index = readAt(pack->file, indexAt, size - kFooterSize - indexAt);
        if (checksum(index) != QByteArrayView(footer).sliced(8, kHashSize)) {
            rejectPack(pack->path);
            continue;
        }
        QDataStream s(index);
        s.setVersion(QDataStream::Qt_6_4);
        quint32 count = 0;
        s >> count;
        if (count > kMaxIndexEntries) {
            rejectPack(pack->path);
            continue;
        }
        const int packIndex = int(m_packs.size());
        for (quint32 i = 0; i < count && s.status() == QDataStream::Ok; ++i) {
            QByteArray id;
            Location where;
            where.pack = packIndex;
            s >> id >> where.offset >> where.length >> where.checksum;
            if (s.status() == QDataStream::Ok && where.offset >= kHeaderSize && where.length >= 0 &&
                where.offset + where.length <= indexAt)
                m_index.insert(id, where);
        }
        m_packs.push_back(std::move(pack));
    }
}

std::optional<QByteArray> AnalysisCache::read(Pack &pack, const Location &where)
{
    QByteArray bytes = readAt(pack.file, where.offset, where.length);
    if (bytes.size() != where.length || entryChecksum(bytes) != where.checksum)
        return std::nullopt;
    return bytes;
}

std::optional<QByteArray> AnalysisCache::load(const QString &kind, const QByteArray &key)
{
    if (!m_enabled)
        return std::nullopt;
    const QByteArray id = entryId(kind, key);
    Location where;
    std::shared_ptr<Pack> pack;
    {
        QMutexLocker lock(&m_mutex);
        if (const auto pending = m_pendingAt.constFind(id); pending != m_pendingAt.constEnd()) {
            ++m_hits;
            return m_pending.at(size_t(*pending)).second;
        }
        if (const auto writing = m_writingAt.constFind(id); writing != m_writingAt.constEnd()) {
            ++m_hits;
            return m_writing.at(size_t(*writing)).second;
        }
        openPacks();
        const auto it = m_index.constFind(id);
        if (it == m_index.constEnd()) {
            ++m_misses;
            return std::nullopt;
        }
        where = *it;
        pack = m_packs.at(size_t(where.pack));
    }
    // Packs are only ever added and removed, never changed in place: reading outside the lock
    // is safe, and a pack removed by another process stays readable through the open handle.
    std::optional<QByteArray> payload = read(*pack, where);
    if (!payload) {
        ++m_rejected;
        ++m_misses;
        return std::nullopt;
    }
    ++m_hits;
    return payload;
}

void AnalysisCache::store(const QString &kind, const QByteArray &key, const QByteArray &payload)
{
    if (!m_enabled)
        return;
    const QByteArray id = entryId(kind, key);
    QMutexLocker lock(&m_mutex);
    if (const auto it = m_pendingAt.constFind(id); it != m_pendingAt.constEnd()) {
        m_pending[size_t(*it)].second = payload;
    } else {
        m_pendingAt.insert(id, qsizetype(m_pending.size()));
        m_pending.emplace_back(id, payload);
    }
    ++m_stores;
}

bool AnalysisCache::writePack(const std::vector<std::pair<QByteArray, QByteArray>> &entries,
                              QString *error) const
{
    qint64 total = kHeaderSize + kFooterSize;
    for (const auto &[id, payload] : entries)
        total += payload.size() + id.size() + 64;
    QByteArray bytes;
    bytes.reserve(total);
    bytes.append(kMagic, 4);
    const quint32 format = qToBigEndian(quint32(kFormatVersion));
    bytes.append(reinterpret_cast<const char *>(&format), 4);
    QByteArray index;
    QDataStream s(&index, QIODevice::WriteOnly);
    s.setVersion(QDataStream::Qt_6_4);
    s << quint32(entries.size());
    for (const auto &[id, payload] : entries) {
        s << id << qint64(bytes.size()) << qint64(payload.size()) << entryChecksum(payload);
        bytes.append(payload);
    }
    const quint64 indexAt = qToBigEndian(quint64(bytes.size()));
    bytes.append(index);
    bytes.append(reinterpret_cast<const char *>(&indexAt), 8);
    bytes.append(checksum(index));
    bytes.append(kFooterMagic, 4);

    // A temporary file renamed into place: readers see no pack or the whole pack. Not synced
    // to disk: a pack a crash leaves incomplete fails its footer and is analysed again.
    QTemporaryFile file(m_directory + QStringLiteral("/.tmp-XXXXXX"));
    file.setAutoRemove(false);
    const bool written = file.open() && file.write(bytes) == bytes.size() && file.flush();
    const QString temporary = file.fileName();
    const QString why = file.errorString();
    file.close();
    const QString path = m_directory + QLatin1Char('/') + packName();
    if (!written || std::rename(QFile::encodeName(temporary).constData(),
                                QFile::encodeName(path).constData()) != 0) {
        if (!temporary.isEmpty())
            QFile::remove(temporary);
        *error = written ? QString::fromLocal8Bit(std::strerror(errno)) : why;
        return false;
    }
    return true;
}

bool AnalysisCache::compact(QString *error)
{
    // The largest pack stays as it is (rewriting it each time would cost what the cache
    // saves); the others and the entries being written become one. Read outside the lock
    // (loads go on meanwhile): packs are never changed in place.
    std::vector<std::shared_ptr<Pack>> packs;
    QHash<QByteArray, Location> index;
    {
        QMutexLocker lock(&m_mutex);
        openPacks();
        packs = m_packs;
        index = m_index;
    }
    size_t largest = 0;
    for (size_t i = 1; i < packs.size(); ++i)
        if (packs[i]->file.size() > packs[largest]->file.size())
            largest = i;
    std::vector<std::pair<QByteArray, QByteArray>> merged;
    for (auto it = index.cbegin(); it != index.cend(); ++it) {
        if (size_t(it->pack) == largest || m_writingAt.contains(it.key()))
            continue;
        if (std::optional<QByteArray> payload = read(*packs.at(size_t(it->pack)), *it))
            merged.emplace_back(it.key(), std::move(*payload));
    }
    merged.insert(merged.end(), m_writing.cbegin(), m_writing.cend());
    if (!writePack(merged, error))
        return false;
    for (size_t i = 0; i < packs.size(); ++i)
        if (i != largest)
            QFile::remove(packs[i]->path); // another process may have removed it already
    return true;
}

void AnalysisCache::flush()
{
    if (m_deferFlush)
        return;
    waitForWrites();
    flushDeferred();
    waitForWrites();
}

void AnalysisCache::flushDeferred()
{
    QMutexLocker writer(&m_writerMutex);
    if (m_writer.joinable()) {
        // Still writing: these entries go with the next flush (loads find them meanwhile), so
        // that writes stay one at a time, in order, and the caller never waits for one.
        if (!m_written.load())
            return;
        m_writer.join();
    }
    if (!m_enabled)
        return;
    {
        QMutexLocker lock(&m_mutex);
        m_writing = std::move(m_pending);
        m_writingAt = std::move(m_pendingAt);
        m_pending.clear();
        m_pendingAt.clear();
    }
    if (m_writing.empty() && !m_digests->changed())
        return;
    // In a long-lived worker the next run goes on while this one's pack is written: the
    // writer yields to it.
    const bool lowPriority = m_deferFlush;
    m_written = false;
    m_writer = std::thread([this, lowPriority] {
        write(lowPriority);
        m_written = true;
    });
}

void AnalysisCache::waitForWrites()
{
    QMutexLocker writer(&m_writerMutex);
    if (m_writer.joinable())
        m_writer.join();
}

void AnalysisCache::write(bool lowPriority)
{
    if (lowPriority)
        lowerThisThreadPriority(BackgroundPriority::Deferred); // this thread's own
    QString error;
    QString problem;
    if (!m_digests->save(&error)) {
        problem = QStringLiteral("The analysis cache could not write its file digests to %1 (%2)")
                      .arg(m_directory, error);
    } else if (!m_writing.empty()) {
        bool merge = false;
        {
            QMutexLocker lock(&m_mutex);
            openPacks();
            merge = int(m_packs.size()) + 1 > kMaxPacks;
        }
        if (!(merge ? compact(&error) : writePack(m_writing, &error)))
            problem = QStringLiteral("The analysis cache could not write to %1 (%2)")
                          .arg(m_directory, error);
    }
    if (!problem.isEmpty())
        fail(problem); // before the entries leave memory: no load sees them gone meanwhile
    const bool wrote = !m_writing.empty() && problem.isEmpty();
    {
        QMutexLocker lock(&m_mutex);
        m_writing.clear();
        m_writingAt.clear();
        if (wrote) {
            // The next load reads the folder again, with this pack and other processes'.
            m_packs.clear();
            m_index.clear();
            m_opened = false;
        }
    }
    if (wrote) {
        m_storedSinceTrim = true;
        trim();
    }
}

void AnalysisCache::fail(const QString &why)
{
    m_enabled = false;
    QMutexLocker lock(&m_mutex);
    if (m_problem.isEmpty())
        m_problem = why + QStringLiteral("; the cache is off for the rest of this run.");
}

std::shared_ptr<const void> AnalysisCache::recent(const QString &kind, const QByteArray &key)
{
    if (!m_enabled)
        return {};
    QMutexLocker lock(&m_recentMutex);
    const auto found = m_recent.find(kind);
    if (found == m_recent.end())
        return {};
    Recent &r = *found;
    if (const auto it = r.current.constFind(key); it != r.current.constEnd()) {
        ++m_hits;
        ++m_kept;
        return *it;
    }
    const auto it = r.previous.find(key);
    if (it == r.previous.end())
        return {};
    std::shared_ptr<const void> value = std::move(*it);
    r.previous.erase(it);
    r.current.insert(key, value);
    ++m_hits;
    ++m_kept;
    return value;
}

void AnalysisCache::keepRecent(const QString &kind, const QByteArray &key,
                               std::shared_ptr<const void> value)
{
    if (!m_enabled)
        return;
    QMutexLocker lock(&m_recentMutex);
    m_recent[kind].current[key] = std::move(value);
}

void AnalysisCache::startRun(std::initializer_list<QString> kinds)
{
    QMutexLocker lock(&m_recentMutex);
    for (const QString &kind : kinds) {
        const auto it = m_recent.find(kind);
        if (it == m_recent.end())
            continue;
        it->previous = std::move(it->current);
        it->current.clear();
    }
}

AnalysisCache::Statistics AnalysisCache::statistics() const
{
    return {m_hits.load(), m_misses.load(), m_rejected.load(), m_stores.load(), m_kept.load()};
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
    const QString folder = m_directory.isEmpty() ? m_root : m_directory;
    d.related.append({QStringLiteral("the analysis cache folder"), Evidence::startOf(folder)});
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
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    QDirIterator it(m_root, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        it.next();
        const QFileInfo info = it.fileInfo();
        const qint64 modified = info.lastModified().toMSecsSinceEpoch();
        total += info.size();
        // Another process's pack being written, or its digest memo: left alone unless stale.
        const bool inUse = (info.fileName().startsWith(QLatin1String(".tmp-")) ||
                            info.fileName().startsWith(QLatin1String("digests."))) &&
                           now - modified < 3600 * 1000;
        if (!inUse)
            entries.push_back({modified, info.size(), info.filePath()});
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
