#pragma once

namespace rosarch {

/// Where the stages keep what they computed for later runs. Core only carries it from a caller
/// to the stages (StageControl::cache): what it is and does belongs to the layer that implements
/// it (the analysis cache, model/cache/), which also gives each stage the cache it was given.
class StageCache
{
public:
    virtual ~StageCache() = default;
    StageCache(const StageCache &) = delete;
    StageCache &operator=(const StageCache &) = delete;

protected:
    StageCache() = default;
};

} // namespace rosarch
