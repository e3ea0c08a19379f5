#pragma once
// Stages 1-3 with a given analysis cache, for the tests of what the cache lets the stages reuse.
#include "cache/analysiscache.h"
#include "pipeline/recovery.h"

namespace rosarch::test {

/// Stages 1-3 on `root` with `cache`, reusing `previous` where recoverWorkspace() can.
inline Recovery recoverWith(const QString &root, AnalysisCache *cache,
                            const Recovery *previous = nullptr)
{
    StageControl control;
    control.cache = cache;
    return recoverWorkspace(root, {}, control, previous);
}

/// Stages 1-3 on `root` without any cache: what a fresh run gives.
inline Recovery recoverUncached(const QString &root)
{
    AnalysisCache off{QString()};
    return recoverWith(root, &off);
}

} // namespace rosarch::test
