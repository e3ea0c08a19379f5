#include "cache/analysiscache.h"

#include <QtConcurrent/QtConcurrentRun>

#include <mutex>

// AnalysisCache's stores left to a pool thread (storeLater) and the wait for them.

namespace rosarch {

namespace {

/// The stores storeLater() began that finishStores() has not waited for.
std::mutex pendingMutex;
QList<QFuture<void>> pending;

} // namespace

void AnalysisCache::storeLater(std::function<void()> store)
{
    // Asking for shared() makes it: only a cache that defers asks.
    if (defersFlush() && this == &shared()) {
        const std::lock_guard lock(pendingMutex);
        pending.append(QtConcurrent::run(std::move(store)));
    } else {
        store();
    }
}

void AnalysisCache::finishStores()
{
    const std::lock_guard lock(pendingMutex);
    for (QFuture<void> &store : pending)
        store.waitForFinished();
    pending.clear();
}

} // namespace rosarch
