// The composed diagram panel's way from a composite to a drawing: the layout graph (built off
// the UI thread for big composites, with the overview check), then the layout (cached, or on
// the DiagramLayouter), then the scene (DiagramPanel::applyLayout).
#include "diagram/diagramlayouter.h"
#include "diagram/diagramoverview.h"
#include "jobs/stallprobe.h"
#include "widgets/diagram/diagramfirstview.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"

#include <QFontMetricsF>

namespace rosarch {

namespace {

int elementCount(const Composite &c)
{
    return int(c.parts.size() + c.channels.size() + c.boundary.size() + c.connections.size());
}

QFont fontFrom(const QString &description)
{
    QFont font;
    font.fromString(description);
    return font;
}

} // namespace

DiagramMetrics DiagramPanel::metrics() const
{
    const DiagramStyle &s = m_scene->diagramStyle();
    return metrics({s.titleFont.toString(), s.textFont.toString(), s.smallFont.toString()});
}

DiagramMetrics DiagramPanel::metrics(const Fonts &fonts)
{
    DiagramMetrics m;
    const auto width = [](const QFont &font) {
        return
            [fm = QFontMetricsF(font)](const QString &text) { return fm.horizontalAdvance(text); };
    };
    const QFont title = fontFrom(fonts.title);
    const QFont text = fontFrom(fonts.text);
    const QFont small = fontFrom(fonts.small);
    m.titleWidth = width(title);
    m.textWidth = width(text);
    m.smallWidth = width(small);
    m.titleHeight = QFontMetricsF(title).height();
    m.textHeight = QFontMetricsF(text).height();
    m.smallHeight = QFontMetricsF(small).height();
    return m;
}

DiagramPanel::Built DiagramPanel::build(const Composite &composite, const DiagramOptions &options,
                                        const DiagramOptions &base, const DiagramMetrics &metrics,
                                        double overviewArea)
{
    Built built;
    built.graph = DiagramBuilder::build(composite, options, metrics);
    // Boxes alone that cover more than the view at the legible zoom cannot fit: a first view
    // that big draws less, but no less than needed: the first of the steps towards the
    // overview whose boxes fit (found by bisection: each step draws fewer boxes than the one
    // before). The layout, bigger than its boxes, may still not fit: overviewInstead decides.
    const auto fits = [overviewArea](const LayoutGraph &graph) {
        return DiagramOverview::boxArea(graph) <= overviewArea;
    };
    if (overviewArea >= 0 && !fits(built.graph)) {
        const QList<DiagramOptions> steps = DiagramFirstView::steps(composite, base);
        int low = DiagramFirstView::indexOf(steps, options) + 1;
        int high = int(steps.size()) - 1;
        int best = high;
        std::optional<LayoutGraph> bestGraph;
        while (low <= high) {
            const int middle = (low + high) / 2;
            LayoutGraph graph = DiagramBuilder::build(composite, steps[middle], metrics);
            if (fits(graph)) {
                best = middle;
                bestGraph = std::move(graph);
                high = middle - 1;
            } else {
                low = middle + 1;
            }
        }
        if (best >= 0 && !DiagramFirstView::sameCollapse(steps[best], options)) {
            built.overview = steps[best];
            built.graph =
                bestGraph ? *bestGraph : DiagramBuilder::build(composite, steps[best], metrics);
        }
    }
    built.dot = GraphLayout::toDot(built.graph);
    return built;
}

void DiagramPanel::relayout()
{
    if (m_pending && m_layouter)
        m_layouter->cancel(); // the previous layout is no longer wanted
    m_pending = false;
    ++m_buildGeneration; // and so is a build in progress
    if (m_building)
        m_builds.cancel();
    m_building = false;
    m_view->setBusyText({});
    const Composite *c = composite();
    if (!c) {
        m_scene->clearDiagram();
        showMessage(m_architecture.composites.isEmpty()
                        ? m_emptyText
                        : tr("This launch file is not part of the architecture."));
        return;
    }
    // The overview check (overviewInstead) is made once, when the composite is first fitted
    // in a view on screen.
    const bool check = !m_sizeChecked.contains(m_current) && m_fitPending && m_view->isVisible();
    const double z = m_view->legibleZoom();
    const QSize viewport = m_view->viewport()->size();
    double overviewArea =
        check && z > 0 ? double(viewport.width()) * viewport.height() / (z * z) : -1.0;
    if (check && m_retryArea >= 0)
        overviewArea = m_retryArea; // the layout came out bigger than its boxes promised
    m_retryArea = -1;
    const DiagramOptions options = currentOptions();
    if (elementCount(*c) <= kInlineBuildElements) {
        onBuilt(build(*c, options, m_options, metrics(), overviewArea));
        return;
    }
    // A big composite (thousands of parts and connections) takes hundreds of milliseconds to
    // build: a worker builds it, from copies, while the panel says so.
    const DiagramStyle &s = m_scene->diagramStyle();
    const Fonts fonts{s.titleFont.toString(), s.textFont.toString(), s.smallFont.toString()};
    const int generation = m_buildGeneration;
    m_building = true;
    m_view->setBusyText(tr("Building diagram…"));
    m_builds.start<Built>(
        [composite = *c, options, base = m_options, fonts, overviewArea](const JobControl &) {
            return build(composite, options, base, metrics(fonts), overviewArea);
        },
        [this, generation](Built built, bool canceled) {
            if (canceled || generation != m_buildGeneration)
                return; // superseded: what the panel shows now was asked for later
            m_building = false;
            m_view->setBusyText({});
            const StallScope scope("DiagramPanel built graph");
            onBuilt(built);
        });
}

void DiagramPanel::onBuilt(const Built &built)
{
    const Composite *c = composite();
    if (!c)
        return;
    if (built.overview)
        setCollapse(*built.overview);
    m_lastBoxArea = DiagramOverview::boxArea(built.graph);
    const LayoutGraph &graph = built.graph;
    if (graph.nodes.isEmpty()) {
        m_scene->clearDiagram();
        showMessage(c->parts.isEmpty()
                        ? tr("%1 starts no nodes and includes no launch files.").arg(c->stem)
                        : tr("Every element of %1 is hidden by the filters.").arg(c->stem));
        Q_EMIT layoutFinished(true);
        return;
    }
    if (graph.nodes.size() > kMaxLayoutNodes) {
        m_scene->clearDiagram();
        const QString what =
            isCollapsed()
                ? tr("%1 has %2 boxes to draw even as an overview; Graphviz would take minutes "
                     "to lay out more than %3.")
                : tr("%1 has %2 boxes to draw; Graphviz would take minutes to lay out more "
                     "than %3. The overview draws fewer.");
        showMessage(what.arg(c->stem).arg(graph.nodes.size()).arg(kMaxLayoutNodes) +
                    QStringLiteral("\n\n") +
                    tr("Open one of the launch files it includes from the launch tree, or hide "
                       "elements with the filters."));
        Q_EMIT layoutFinished(false);
        return;
    }
    if (!m_layouter)
        return; // the window is closing
    if (const std::optional<LayoutGeometry> cached = m_layouter->cached(built.dot)) {
        LayoutResult result;
        result.ok = true;
        result.geometry = *cached;
        applyLayout(graph, result, m_fitPending);
        return;
    }
    m_pending = true;
    m_view->setBusyText(tr("Laying out…"));
    m_layouter->layout(graph, built.dot, [this, graph](const LayoutResult &result) {
        m_pending = false;
        m_view->setBusyText({});
        applyLayout(graph, result, m_fitPending);
    });
}

} // namespace rosarch
