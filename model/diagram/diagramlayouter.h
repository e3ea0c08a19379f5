#pragma once

#include "diagram/graphlayout.h"
#include "jobs/jobrunner.h"

#include <QHash>
#include <QObject>
#include <QStringList>

#include <functional>
#include <optional>

namespace rosarch {

/// Lays out diagrams off the UI thread on a JobRunner, one at a time: a new request supersedes
/// the one in progress (its helper process is killed and its result dropped). Results are
/// cached by the graph's DOT text, so going back to a composite shows it at once.
class DiagramLayouter : public QObject
{
    Q_OBJECT
public:
    explicit DiagramLayouter(QObject *parent = nullptr);

    /// Graphviz gets this long per layout before the request fails (default 20 s).
    void setTimeout(int milliseconds) { m_timeoutMs = milliseconds; }
    int timeout() const { return m_timeoutMs; }

    /// The layout of `graph` computed before, if it is still cached.
    std::optional<LayoutGeometry> cached(const LayoutGraph &graph) const;
    /// The same, for a graph whose DOT text (GraphLayout::toDot) is `dot`: a big graph's DOT
    /// is made off the UI thread.
    std::optional<LayoutGeometry> cached(const QString &dot) const;
    /// Lays `graph` out, superseding a layout in progress; `done` is called on this object's
    /// thread with the result, unless the request was superseded or canceled.
    void layout(const LayoutGraph &graph, std::function<void(const LayoutResult &)> done);
    /// The same, with the graph's DOT text made already.
    void layout(const LayoutGraph &graph, const QString &dot,
                std::function<void(const LayoutResult &)> done);
    /// Drops the layout in progress: its `done` is not called.
    void cancel();
    bool isRunning() const { return m_jobs.isRunning(); }

private:
    static constexpr qsizetype kCacheSize = 32;

    int m_timeoutMs = 20000;
    QHash<QString, LayoutGeometry> m_cache; ///< by DOT text
    QStringList m_cacheOrder;               ///< oldest first
    JobRunner m_jobs;                       ///< last: its destructor stops the helper and waits
};

} // namespace rosarch
