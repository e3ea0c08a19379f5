#pragma once

namespace rosarch {

class AnalysisCache;

/// Keeps an in-process recovery from waiting for its cache packs, as the worker does by writing
/// them after its reply: while this lives, the shared cache's flushes are deferred (what the
/// stages store stays in memory, where their loads find it), and when it goes a thread of this
/// process writes them (AnalysisCache::flushDeferred) while the caller goes on with the result.
/// The writes end before the process does, so a headless run still leaves a complete cache; a
/// write that fails is said by the next run (AnalysisCache::takeProblem), as the worker's is.
/// A cache that defers already (the worker's) is left as it is, and so is one the caller owns
/// (StageControl::cache): nothing here may outlive it, so it is written at once, as before.
class DeferredCacheWrite
{
public:
    explicit DeferredCacheWrite(AnalysisCache &cache);
    ~DeferredCacheWrite();
    DeferredCacheWrite(const DeferredCacheWrite &) = delete;
    DeferredCacheWrite &operator=(const DeferredCacheWrite &) = delete;

    /// Waits until every write started so far has ended (it happens at exit too).
    static void waitForWrites();

private:
    AnalysisCache *m_deferred = nullptr; ///< the cache whose flushes this defers, or null
};

} // namespace rosarch
