#include "diagram/diagramlayouter.h"

namespace rosarch {

DiagramLayouter::DiagramLayouter(QObject *parent) : QObject(parent) {}

std::optional<LayoutGeometry> DiagramLayouter::cached(const LayoutGraph &graph) const
{
    return cached(GraphLayout::toDot(graph));
}

std::optional<LayoutGeometry> DiagramLayouter::cached(const QString &dot) const
{
    const auto it = m_cache.constFind(dot);
    if (it == m_cache.cend())
        return std::nullopt;
    return *it;
}

void DiagramLayouter::layout(const LayoutGraph &graph,
                             std::function<void(const LayoutResult &)> done)
{
    layout(graph, GraphLayout::toDot(graph), std::move(done));
}

void DiagramLayouter::layout(const LayoutGraph &graph, const QString &dot,
                             std::function<void(const LayoutResult &)> done)
{
    LayoutOptions options;
    options.timeoutMs = m_timeoutMs;
    m_jobs.start<LayoutResult>(
        [graph, options](const JobControl &control) mutable {
            options.canceled = [&control] { return control.isCanceled(); };
            return GraphLayout::layout(graph, options);
        },
        [this, dot, done = std::move(done)](LayoutResult result, bool canceled) {
            if (canceled)
                return; // superseded on purpose; the new request reports
            if (result.ok) {
                m_cache.insert(dot, result.geometry);
                m_cacheOrder << dot;
                if (m_cacheOrder.size() > kCacheSize)
                    m_cache.remove(m_cacheOrder.takeFirst());
            }
            done(result);
        });
}

void DiagramLayouter::cancel()
{
    m_jobs.cancel();
}

} // namespace rosarch
