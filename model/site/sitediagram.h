#pragma once

#include "core/composition.h"
#include "diagram/graphlayout.h"
#include "diagram/layoutgraph.h"

#include <QString>

#include <functional>

namespace rosarch {

/// A composed diagram as inline SVG for the site: DiagramBuilder's graph (the overview, as
/// the GUI starts a composite too big to read, when it is big), laid out by Graphviz, drawn with
/// CSS classes (so the page's light or dark scheme colours it) and with a link on every part,
/// channel and port that has a page.
class SiteDiagram
{
public:
    struct Result
    {
        QString svg;           ///< "" when the layout failed
        QString error;         ///< why, for the page
        bool overview = false; ///< namespaces were collapsed to fit
        int elements = 0;      ///< boxes drawn
    };
    /// `hrefOf(key)` gives a diagram key's link ("" = none) as the page writes it; `id` makes
    /// the SVG's element ids unique in its page.
    static Result draw(const Composite &composite, const QString &title, const QString &id,
                       const std::function<QString(const QString &key)> &hrefOf);
    /// The layout of `graph`: by the layout helper (rosarch-layout) when there is one, which
    /// contains Graphviz's crashes and has a time limit, else in this process.
    static LayoutResult layout(const LayoutGraph &graph);
    /// The SVG for an already laid-out graph (exposed for the tests).
    static QString svg(const LayoutGraph &graph, const LayoutGeometry &geometry,
                       const QString &title, const QString &id,
                       const std::function<QString(const QString &key)> &hrefOf);
};

} // namespace rosarch
