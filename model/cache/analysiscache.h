#pragma once

#include "cache/filedigests.h"
#include "core/diagnostic.h"
#include "core/stagecache.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QHash>
#include <QMutex>
#include <QSet>
#include <QString>

#include <atomic>
#include <functional>
#include <initializer_list>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

class QFile;

namespace rosarch {

struct StageControl;

/// Analysis results on disk, keyed by a hash of everything a result depends on (see key()).
/// Lives in the user's cache folder (`<cache>/rosarch/analysis/<version>-f<format>/`) as pack
/// files: the entries a run stores are written at its end (flush()) as one pack, a temporary
/// file renamed into place, with an index at its end that a later run reads once.
/// - every entry carries a checksum: a truncated, damaged or foreign entry or pack is a miss
///   and is analysed again; a pack that another process removes meanwhile is a miss too;
/// - a folder that cannot be created or written, or a full disk, turns the cache off for the
///   rest of the run, with one `cache-unavailable` diagnostic (takeProblem());
/// - the cache is bounded (ROSARCH_CACHE_MAX_MB, default 256): trim() removes the oldest packs
///   past the bound, and flush() merges the packs when there are many;
/// - it also keeps the file digests memo (digests()), so that unchanged files need no reading.
/// Thread-safe: the analyzers load and store from their worker threads; two processes may use
/// one folder at once (each writes its own packs, under unique names).
/// The stages are given it in StageControl::cache and take it from there with of().
class AnalysisCache : public StageCache
{
public:
    /// Bump when the serialised form of any cached result changes.
    static constexpr int kFormatVersion = 23;
    static constexpr qint64 kDefaultMaxBytes = 256LL * 1024 * 1024;
    /// More packs than this in the folder are merged into one at flush().
    static constexpr int kMaxPacks = 8;

    /// What happened in this cache since it was opened.
    struct Statistics
    {
        int hits = 0;
        int misses = 0;   ///< no entry (or an unusable one) for a key
        int rejected = 0; ///< entries found damaged or foreign (counted as misses too)
        int stores = 0;
        int kept = 0; ///< hits served by values this process decoded before (recent())
    };

    /// A cache in `root` (entries below `root`/analysis/); "" gives a cache that is off.
    /// `racyWindowNs` is its file digests' (FileDigests); tests pass 0.
    explicit AnalysisCache(const QString &root, qint64 maxBytes = kDefaultMaxBytes,
                           qint64 racyWindowNs = FileDigests::kDefaultRacyWindowNs);
    ~AnalysisCache() override;
    AnalysisCache(const AnalysisCache &) = delete;
    AnalysisCache &operator=(const AnalysisCache &) = delete;

    /// The cache of this process: off with ROSARCH_NO_CACHE=1, else in $ROSARCH_CACHE_DIR,
    /// else in `<GenericCacheLocation>/rosarch`; bounded by $ROSARCH_CACHE_MAX_MB.
    static AnalysisCache &shared();
    /// The cache `control` gives a stage; when it gives none, one that is off (nothing is
    /// looked up or stored).
    static AnalysisCache &of(const StageControl &control);
    /// The root shared() uses ("" when the cache is off).
    static QString defaultRoot();
    /// The size bound shared() uses: $ROSARCH_CACHE_MAX_MB megabytes, else kDefaultMaxBytes.
    static qint64 defaultMaxBytes();

    bool isEnabled() const { return m_enabled.load(); }
    /// The folder of this build's packs.
    QString directory() const { return m_directory; }

    /// The key of a result that depends on exactly `parts` (each given in full).
    static QByteArray key(std::initializer_list<QByteArrayView> parts);

    /// The entry of `kind` ("cpp", "python", "launch", ...) for `key`, if there is a good one.
    std::optional<QByteArray> load(const QString &kind, const QByteArray &key);
    /// Stores an entry (on disk at the next flush()).
    void store(const QString &kind, const QByteArray &key, const QByteArray &payload);

    /// The digests of files, memoised in this cache's folder (not kept when the cache is off).
    FileDigests &digests() { return *m_digests; }

    /// Writes the entries stored since the last flush as one pack and the digest memo, then
    /// trims; a failure turns the cache off (see takeProblem()). Waits for flushDeferred() when
    /// deferred (setDeferFlush()).
    void flush();
    /// In a long-lived worker: flush() leaves what was stored in memory (loads find it there)
    /// until flushDeferred(), called once the worker has replied, so that a run does not wait for
    /// its pack to be written; a problem writing it is said by the next run.
    void setDeferFlush(bool defer) { m_deferFlush = defer; }
    bool defersFlush() const { return m_deferFlush; }
    /// Flushes, deferred or not, without waiting: the entries stored so far are written by a
    /// thread of low priority (loads find them in memory meanwhile); while one is still being
    /// written, they wait in memory for the next call. The next run goes on at once.
    void flushDeferred();
    /// Waits for the write flushDeferred() began (the destructor waits, then writes the rest).
    void waitForWrites();
    /// Runs `store` (which stores entries in this cache) on a pool thread when this is the
    /// shared cache and defers its flushes, to be waited for by finishStores(); else now. For
    /// what a run encodes once its result is known (stage 1's C++ facts, the memos of stages 2
    /// and 3), so that encoding does not hold up the result.
    void storeLater(std::function<void()> store);
    /// Waits until what storeLater() began is stored. Whoever writes the shared cache's pack
    /// calls this first.
    static void finishStores();

    /// Values decoded from entries in this process, so that a long-lived worker does not decode
    /// the same entries run after run (stagememo::load gives them their types; one kind, one
    /// type). What a run of a kind used stays for the next run of that kind (startRun()); the
    /// rest is dropped then. A kept value counts as a hit. Nothing is kept when the cache is off.
    std::shared_ptr<const void> recent(const QString &kind, const QByteArray &key);
    void keepRecent(const QString &kind, const QByteArray &key, std::shared_ptr<const void> value);
    /// A new run of `kinds` begins: drops their values that the previous run did not use.
    void startRun(std::initializer_list<QString> kinds);

    Statistics statistics() const;
    /// The diagnostic for the problem that turned the cache off, once; none otherwise.
    std::optional<Diagnostic> takeProblem();

    /// Removes the oldest packs (of every version) while all of them exceed the size bound,
    /// when anything was stored since the last trim.
    void trim();

private:
    struct Pack;
    struct Location
    {
        int pack = -1; ///< in m_packs
        qint64 offset = 0;
        qint64 length = 0;
        QByteArray checksum;
    };
    static QByteArray entryId(const QString &kind, const QByteArray &key);
    void openPacks();
    void rejectPack(const QString &path);
    static std::optional<QByteArray> read(Pack &pack, const Location &where);
    bool writePack(const std::vector<std::pair<QByteArray, QByteArray>> &entries,
                   QString *error) const;
    bool compact(QString *error);
    void write(bool lowPriority);
    void fail(const QString &why);

    QString m_root;
    QString m_directory;
    qint64 m_maxBytes;
    std::atomic<bool> m_enabled{false};
    std::atomic<int> m_hits{0}, m_misses{0}, m_rejected{0}, m_stores{0}, m_kept{0};
    std::atomic<bool> m_storedSinceTrim{false};
    std::atomic<bool> m_deferFlush{false};
    std::unique_ptr<FileDigests> m_digests;

    mutable QMutex m_mutex; ///< guards everything below
    bool m_opened = false;
    std::vector<std::shared_ptr<Pack>> m_packs; ///< shared with loads reading outside the lock
    QHash<QByteArray, Location> m_index;        ///< entryId -> where
    std::vector<std::pair<QByteArray, QByteArray>> m_pending; ///< entryId, payload
    QHash<QByteArray, qsizetype> m_pendingAt;                 ///< entryId -> in m_pending
    /// Entries being written by m_writer: changed only while no write runs (flushDeferred())
    /// and, under the lock, by the writer when it is done.
    std::vector<std::pair<QByteArray, QByteArray>> m_writing;
    QHash<QByteArray, qsizetype> m_writingAt;
    QSet<QString> m_rejectedPacks;
    QString m_problem;
    bool m_problemTaken = false;

    QMutex m_writerMutex; ///< guards m_writer: one write at a time, in the order begun
    std::thread m_writer;
    std::atomic<bool> m_written{true}; ///< m_writer is done

    struct Recent
    {
        QHash<QByteArray, std::shared_ptr<const void>> current;  ///< used in this run
        QHash<QByteArray, std::shared_ptr<const void>> previous; ///< used in the one before
    };
    QMutex m_recentMutex; ///< guards m_recent
    QHash<QString, Recent> m_recent;
};

} // namespace rosarch
