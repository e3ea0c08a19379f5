#pragma once

#include <sys/resource.h>
#include <unistd.h>

namespace rosarch {

/// How far background threads step back for the work a person waits for.
enum class BackgroundPriority
{
    /// The window's own background work (stable keys, freeing an old model), which starts just
    /// as a result is shown and painted: a nice-0 thread (the UI's) gets about three times its
    /// share of a core.
    YieldToUi = 5,
    /// Work whose result nobody waits for now (writing the cache's pack after the reply).
    Deferred = 10,
    /// Work done only with what the rest of the machine leaves (the worker's idle warm-up).
    Idle = 19,
};

/// Lowers the calling thread's priority (its nice value). On Linux a thread's nice value is its
/// own, and a process cannot raise it again: call it only on threads made for such work (a
/// thread of its own, or a pool kept for it). Best effort: when refused it does nothing.
inline void lowerThisThreadPriority(BackgroundPriority priority)
{
#ifdef __linux__
    setpriority(PRIO_PROCESS, id_t(::gettid()), int(priority));
#endif
}

} // namespace rosarch
