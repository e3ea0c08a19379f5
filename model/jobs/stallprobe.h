#pragma once

#include <QElapsedTimer>

#include <atomic>

namespace rosarch {

/// Names stretches of work on the UI thread for the stall benchmark (tools/stallbench), which
/// reports what ran during the longest gaps of the event loop. Without a sink (always, outside
/// the benchmark) a scope costs one atomic load.
class StallProbe
{
public:
    /// Receives each finished scope: its name, how long it took and how deep it was nested.
    using Sink = void (*)(const char *name, qint64 nanoseconds, int depth);
    static void setSink(Sink sink) { s_sink.store(sink); }
    static Sink sink() { return s_sink.load(std::memory_order_relaxed); }

private:
    friend class StallScope;
    static inline std::atomic<Sink> s_sink{nullptr};
    static inline thread_local int s_depth = 0;
};

/// One named stretch of work (a string literal), reported to the StallProbe's sink.
class StallScope
{
public:
    explicit StallScope(const char *name) : m_name(name), m_sink(StallProbe::sink())
    {
        if (m_sink) {
            ++StallProbe::s_depth;
            m_timer.start();
        }
    }
    ~StallScope()
    {
        if (m_sink)
            m_sink(m_name, m_timer.nsecsElapsed(), --StallProbe::s_depth);
    }
    StallScope(const StallScope &) = delete;
    StallScope &operator=(const StallScope &) = delete;

private:
    const char *m_name;
    StallProbe::Sink m_sink;
    QElapsedTimer m_timer;
};

} // namespace rosarch
