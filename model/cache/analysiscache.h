#pragma once

#include "diagnostic.h"

#include <QByteArray>
#include <QByteArrayView>
#include <QMutex>
#include <QString>

#include <atomic>
#include <initializer_list>
#include <optional>

namespace rosarch {

/// Per-file analysis results on disk, keyed by a hash of everything a result depends on (the
/// file's content, its path, its package, ...; see key()). Lives in the user's cache folder
/// (`<cache>/rosarch/analysis/<version>-f<format>/<kind>/<xx>/<key>`), one file per entry.
/// - an entry is written atomically (a temporary file renamed) and carries a checksum: a truncated,
/// damaged
///   or foreign entry is a miss and is analysed again;
/// - a folder that cannot be created or written, or a full disk, turns the cache off for the
///   rest of the run, with one `cache-unavailable` diagnostic (takeProblem());
/// - the cache is bounded: trim() removes the oldest entries past the size bound.
/// Thread-safe: the analyzers load and store from their worker threads.
class AnalysisCache
{
public:
    /// Bump when the serialised form of any cached result changes.
    static constexpr int kFormatVersion = 1;
    static constexpr qint64 kDefaultMaxBytes = 256LL * 1024 * 1024;

    /// What happened in this cache since it was opened.
    struct Statistics
    {
        int hits = 0;
        int misses = 0;   ///< no entry (or an unusable one) for a key
        int rejected = 0; ///< entries found damaged or foreign (counted as misses too)
        int stores = 0;
    };

    /// A cache in `root` (entries below `root`/analysis/); "" gives a cache that is off.
    explicit AnalysisCache(const QString &root, qint64 maxBytes = kDefaultMaxBytes);
    AnalysisCache(const AnalysisCache &) = delete;
    AnalysisCache &operator=(const AnalysisCache &) = delete;

    /// The cache of this process: off with ROSARCH_NO_CACHE=1, else in $ROSARCH_CACHE_DIR,
    /// else in `<GenericCacheLocation>/rosarch`.
    static AnalysisCache &shared();
    /// The root shared() uses ("" when the cache is off).
    static QString defaultRoot();

    bool isEnabled() const { return m_enabled.load(); }
    /// The folder of this build's entries.
    QString directory() const { return m_directory; }

    /// The key of a result that depends on exactly `parts` (each given in full).
    static QByteArray key(std::initializer_list<QByteArrayView> parts);

    /// The entry of `kind` ("cpp", "python", "launch", ...) for `key`, if there is a good one.
    std::optional<QByteArray> load(const QString &kind, const QByteArray &key);
    /// Stores an entry; a failure turns the cache off (see takeProblem()).
    void store(const QString &kind, const QByteArray &key, const QByteArray &payload);

    Statistics statistics() const;
    /// The diagnostic for the problem that turned the cache off, once; none otherwise.
    std::optional<Diagnostic> takeProblem();

    /// Removes the oldest entries (of every version) while all of them exceed the size bound,
    /// when anything was stored since the last trim.
    void trim();

private:
    QString entryPath(const QString &kind, const QByteArray &key) const;
    void fail(const QString &why);

    QString m_root;
    QString m_directory;
    qint64 m_maxBytes;
    std::atomic<bool> m_enabled{false};
    std::atomic<int> m_hits{0}, m_misses{0}, m_rejected{0}, m_stores{0};
    std::atomic<bool> m_storedSinceTrim{false};
    QMutex m_mutex; ///< guards the problem
    QString m_problem;
    bool m_problemTaken = false;
};

} // namespace rosarch
