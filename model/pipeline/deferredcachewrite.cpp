#include "pipeline/deferredcachewrite.h"
#include "cache/analysiscache.h"

#include <mutex>
#include <thread>

namespace rosarch {

namespace {

/// The thread writing the latest deferred pack; joined before the next starts and at exit.
class Writes
{
public:
    // The shared cache first: statics go in the reverse order of their construction, so this
    // is gone, its thread joined, before the cache is.
    Writes() : m_cache(&AnalysisCache::shared()) {}
    ~Writes()
    {
        wait();
        AnalysisCache::finishStores(); // the worker's, whose pack is written after its reply
    }
    Writes(const Writes &) = delete;
    Writes &operator=(const Writes &) = delete;

    void start()
    {
        const std::lock_guard lock(m_mutex);
        if (m_thread.joinable()) // one write at a time; the previous run's is long done
            m_thread.join();
        m_thread = std::thread([cache = m_cache] {
            AnalysisCache::finishStores();
            cache->flushDeferred();
        });
    }
    void wait()
    {
        const std::lock_guard lock(m_mutex);
        if (m_thread.joinable())
            m_thread.join();
        m_cache->waitForWrites(); // flushDeferred() hands the pack to the cache's own writer
    }

private:
    AnalysisCache *m_cache;
    std::mutex m_mutex;
    std::thread m_thread;
};

Writes &writes()
{
    static Writes w;
    return w;
}

/// Whether a run defers the shared cache's flushes now (one run at a time does: the one that
/// turned deferral on turns it off and starts the write).
std::mutex deferMutex;

} // namespace

DeferredCacheWrite::DeferredCacheWrite(AnalysisCache &cache)
{
    if (&cache != &AnalysisCache::shared() || !cache.isEnabled())
        return;
    writes(); // constructed after the cache, see Writes
    const std::lock_guard lock(deferMutex);
    if (cache.defersFlush())
        return; // the worker's, or another run's in this process
    cache.setDeferFlush(true);
    m_deferred = &cache;
}

DeferredCacheWrite::~DeferredCacheWrite()
{
    if (!m_deferred)
        return;
    {
        const std::lock_guard lock(deferMutex);
        m_deferred->setDeferFlush(false);
    }
    writes().start();
}

void DeferredCacheWrite::waitForWrites()
{
    writes().wait();
}

} // namespace rosarch
