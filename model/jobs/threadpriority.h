#pragma once

#include <sys/resource.h>
#include <unistd.h>

namespace rosarch {

/// Lowers the calling thread's priority, so that on a busy machine it yields the core to the UI
/// thread: the window's background work (stable keys, freeing an old model) starts just as a
/// result is shown and painted, which on two cores took the UI thread's time away. On Linux a
/// thread's nice value is its own, and a process cannot raise it again: call it only on threads
/// of a pool kept for such work. Elsewhere, and when refused, it does nothing.
inline void lowerThisThreadPriority()
{
#ifdef __linux__
    constexpr int kNice = 5; // a nice-0 thread gets about three times its share of a core
    setpriority(PRIO_PROCESS, id_t(::gettid()), kNice); // best effort
#endif
}

} // namespace rosarch
