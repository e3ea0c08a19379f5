#pragma once

#include "diagram/layoutgraph.h"

#include <QString>

#include <functional>

namespace rosarch {

/// How GraphLayout::layout runs the helper.
struct LayoutOptions
{
    int timeoutMs = 20000;          ///< the helper is killed after this long
    QString helperPath;             ///< "" = $ROSARCH_LAYOUT, next to the application, libexec
    std::function<bool()> canceled; ///< polled while the helper runs; true kills it
};

/// The outcome of a layout: coordinates, or a message that says in words what went wrong.
struct LayoutResult
{
    bool ok = false;
    bool canceled = false;
    QString error;
    LayoutGeometry geometry;
    qint64 elapsedMs = 0;
};

/// Graphviz `dot` layout as a pure function: the graph goes out as DOT to the rosarch-layout
/// helper process (Graphviz can abort() or run for minutes on some inputs), coordinates come
/// back. Safe to call from any thread; nothing is shared between calls.
class GraphLayout
{
public:
    /// The DOT text for `graph`: the same graph always gives the same text.
    static QString toDot(const LayoutGraph &graph);
    /// Lays `graph` out left to right; blocks the calling thread until the helper is done.
    static LayoutResult layout(const LayoutGraph &graph, const LayoutOptions &options = {});
    /// The helper executable that layout() would run ("" when there is none).
    static QString helperPath(const LayoutOptions &options = {});
    /// Reads the helper's JSON output into coordinates keyed by the ids of `graph`.
    static bool parseGeometry(const QByteArray &json, const LayoutGraph &graph,
                              LayoutGeometry *geometry, QString *error);
};

} // namespace rosarch
