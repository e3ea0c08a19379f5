#include "site/sitediagram.h"
#include "diagram/diagrambuilder.h"
#include "diagram/diagramoverview.h"
#include "diagram/graphlayout.h"
#include "site/inprocesslayout.h"
#include "site/sitehtml.h"

#include <QCoreApplication>

#include <cmath>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::SiteDiagram", text);
}

/// Beyond this many square points of boxes a diagram is not readable on a page: the overview.
constexpr double kOverviewArea = 1600.0 * 1200.0;
constexpr int kLayoutTimeoutMs = 20000;
constexpr double kMargin = 8;
constexpr double kPortSquare = 8;
constexpr double kPortInset = 12;

QString num(double v)
{
    // Whole tenths: short, and the same text for the same layout on every machine.
    const double r = std::round(v * 10) / 10;
    return QString::number(r == 0 ? 0.0 : r, 'f', r == std::round(r) ? 0 : 1);
}

QString pt(const QPointF &p)
{
    return num(p.x()) + u',' + num(p.y());
}

/// `text` cut to about `width` points of `perCharacter`-wide characters.
QString fitted(const QString &text, double width, double perCharacter)
{
    const int room = std::max(3, int(width / perCharacter));
    if (text.size() <= room)
        return text;
    const int head = (room - 1) / 2;
    return text.left(head) + QChar(0x2026) + text.right(room - 1 - head);
}

QString shapePath(const LayoutNode &n, const QRectF &r)
{
    const double x = r.x();
    const double y = r.y();
    const double w = r.width();
    const double h = r.height();
    switch (n.shape) {
    case LayoutNode::Shape::Ellipse:
        return QStringLiteral("<ellipse class=\"shape\" cx=\"%1\" cy=\"%2\" rx=\"%3\" ry=\"%4\"/>")
            .arg(num(r.center().x()), num(r.center().y()), num(w / 2), num(h / 2));
    case LayoutNode::Shape::Hexagon:
        return QStringLiteral("<polygon class=\"shape\" points=\"%1 %2 %3 %4 %5 %6\"/>")
            .arg(pt({x, y + h / 2}), pt({x + w / 4, y}), pt({x + 3 * w / 4, y}),
                 pt({x + w, y + h / 2}), pt({x + 3 * w / 4, y + h}), pt({x + w / 4, y + h}));
    case LayoutNode::Shape::Queue: {
        const double rx = std::min(7.0, w / 6);
        return QStringLiteral("<path class=\"shape\" d=\"M%1 H%2 A%3 %4 0 0 1 %5 H%6 A%3 %4 0 0 1 "
                              "%1 Z\"/><path class=\"rim\" d=\"M%7 A%3 %4 0 0 0 %5\"/>")
            .arg(pt({x + rx, y}), num(x + w - rx), num(rx), num(h / 2), pt({x + w - rx, y + h}),
                 num(x + rx), pt({x + w - rx, y}));
    }
    case LayoutNode::Shape::Folder:
    case LayoutNode::Shape::Tag:
    case LayoutNode::Shape::Box:
        break;
    }
    return QStringLiteral("<rect class=\"shape\" x=\"%1\" y=\"%2\" width=\"%3\" height=\"%4\" "
                          "rx=\"%5\"/>")
        .arg(num(x), num(y), num(w), num(h),
             n.shape == LayoutNode::Shape::Box ? QLatin1String("7") : QLatin1String("4"));
}

QString nodeClass(const LayoutNode &n)
{
    QString c;
    switch (n.shape) {
    case LayoutNode::Shape::Queue:
        c = QStringLiteral("topic");
        break;
    case LayoutNode::Shape::Ellipse:
        c = QStringLiteral("service");
        break;
    case LayoutNode::Shape::Hexagon:
        c = QStringLiteral("action");
        break;
    case LayoutNode::Shape::Tag:
        c = QStringLiteral("boundary");
        break;
    case LayoutNode::Shape::Folder:
        c = QStringLiteral("collapsed");
        break;
    case LayoutNode::Shape::Box:
        c = n.flags & (LayoutOpenable | LayoutExternal) ? QStringLiteral("part include")
                                                        : QStringLiteral("part");
        break;
    }
    if (n.flags & LayoutInactive)
        c += QStringLiteral(" inactive");
    if (n.flags & LayoutUnresolved)
        c += QStringLiteral(" unresolved");
    if (n.flags & (LayoutCorrected | LayoutSuggested))
        c += QStringLiteral(" corrected");
    return c;
}

QString anchorOpen(const QString &href, const QString &label)
{
    if (href.isEmpty())
        return QStringLiteral("<g><title>%1</title>").arg(SiteHtml::escape(label));
    return QStringLiteral("<a href=\"%1\"><title>%2</title>")
        .arg(SiteHtml::escape(href), SiteHtml::escape(label));
}

QString anchorClose(const QString &href)
{
    return href.isEmpty() ? QStringLiteral("</g>") : QStringLiteral("</a>");
}

QString nodeSvg(const LayoutNode &n, const QRectF &r,
                const std::function<QString(const QString &)> &hrefOf)
{
    const bool box = n.shape == LayoutNode::Shape::Box;
    const QString href = hrefOf(n.key);
    const QString name =
        n.detail.isEmpty() ? n.label : n.label + QStringLiteral(" (") + n.detail + u')';
    QString out = QStringLiteral("<g class=\"%1\">").arg(nodeClass(n));
    out += anchorOpen(href, name);
    out += shapePath(n, r);
    const double inner = r.width() - 12;
    const double top = box ? r.y() + 8 + 12 : r.center().y() - (n.detail.isEmpty() ? -4 : 3);
    out += QStringLiteral("<text class=\"%1\" x=\"%2\" y=\"%3\">%4</text>")
               .arg(box || n.shape == LayoutNode::Shape::Folder ? QLatin1String("title")
                                                                : QLatin1String("label"),
                    num(r.center().x()), num(top),
                    SiteHtml::escape(fitted(n.label, inner, box ? 7 : 6.5)));
    if (!n.detail.isEmpty())
        out += QStringLiteral("<text class=\"detail\" x=\"%1\" y=\"%2\">%3</text>")
                   .arg(num(r.center().x()), num(top + 13),
                        SiteHtml::escape(fitted(n.detail, inner, 5.6)));
    out += anchorClose(href);
    for (const LayoutPort &port : n.ports) {
        const QPointF a = r.topLeft() + n.portAnchor(port.id);
        const QString portHref = hrefOf(port.key);
        out += QStringLiteral("<g class=\"port%1\">")
                   .arg(port.flags & LayoutInactive ? QStringLiteral(" inactive") : QString());
        out += anchorOpen(portHref, port.label);
        out +=
            QStringLiteral("<rect x=\"%1\" y=\"%2\" width=\"%3\" height=\"%3\"/>")
                .arg(num(a.x() - kPortSquare / 2), num(a.y() - kPortSquare / 2), num(kPortSquare));
        // As the GUI elides it: the row's whole width, for a node has few ports on both sides.
        const double width = r.width() - 2 * kPortInset;
        out += QStringLiteral("<text class=\"%1\" x=\"%2\" y=\"%3\">%4</text>")
                   .arg(port.input ? QLatin1String("in") : QLatin1String("out"),
                        num(port.input ? a.x() + kPortInset : a.x() - kPortInset), num(a.y() + 3.5),
                        SiteHtml::escape(fitted(port.label, width, 5.6)));
        out += anchorClose(portHref) + QStringLiteral("</g>");
    }
    return out + QStringLiteral("</g>\n");
}

QString edgeSvg(const LayoutEdge &e, const EdgeGeometry &g)
{
    static const char *const kinds[] = {"pub", "sub", "cli", "srv", "din", "dout"};
    const char *kind = e.category >= 0 && e.category < 6 ? kinds[e.category] : "pub";
    if (g.points.isEmpty())
        return {};
    QString d = QStringLiteral("M") + pt(g.points.first());
    for (qsizetype i = 1; i + 2 < g.points.size(); i += 3)
        d += QStringLiteral(" C") + pt(g.points[i]) + u' ' + pt(g.points[i + 1]) + u' ' +
             pt(g.points[i + 2]);
    QString out =
        QStringLiteral("<g class=\"edge %1\"><path d=\"%2\"/>").arg(QLatin1String(kind), d);
    const auto head = [&](const QPointF &from, const QPointF &tip) {
        const QPointF v = tip - from;
        const double length = std::hypot(v.x(), v.y());
        if (length < 0.01)
            return QString();
        const QPointF u = v / length;
        const QPointF side(-u.y() * 3.5, u.x() * 3.5);
        const QPointF base = tip - u * std::max(length, 7.0);
        return QStringLiteral("<polygon points=\"%1 %2 %3\"/>")
            .arg(pt(tip), pt(base + side), pt(base - side));
    };
    if (g.hasArrowEnd)
        out += head(g.points.last(), g.arrowEnd);
    if (g.hasArrowStart)
        out += head(g.points.first(), g.arrowStart);
    return out + QStringLiteral("</g>\n");
}

} // namespace

QString SiteDiagram::svg(const LayoutGraph &graph, const LayoutGeometry &geometry,
                         const QString &title, const QString &id,
                         const std::function<QString(const QString &key)> &hrefOf)
{
    const QRectF b = geometry.bounds.adjusted(-kMargin, -kMargin, kMargin, kMargin);
    QString out =
        QStringLiteral("<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"diagram\" "
                       "viewBox=\"%1 %2 %3 %4\" width=\"%3\" height=\"%4\" "
                       "aria-labelledby=\"%5-title\">\n<title id=\"%5-title\">%6</title>\n")
            .arg(num(b.x()), num(b.y()), num(b.width()), num(b.height()), id,
                 SiteHtml::escape(title));
    for (const LayoutCluster &c : graph.clusters) {
        const QRectF r = geometry.clusters.value(c.id);
        if (r.isNull())
            continue;
        const bool subsystem = c.key.startsWith(QLatin1String("subsystem:"));
        out += QStringLiteral("<g class=\"cluster%1\"><rect x=\"%2\" y=\"%3\" width=\"%4\" "
                              "height=\"%5\" rx=\"6\"/><text x=\"%6\" y=\"%7\">%8</text></g>\n")
                   .arg(subsystem ? QStringLiteral(" subsystem") : QString(), num(r.x()),
                        num(r.y()), num(r.width()), num(r.height()), num(r.x() + 8),
                        num(r.y() + 14), SiteHtml::escape(fitted(c.label, r.width() - 16, 6.5)));
    }
    for (const LayoutEdge &e : graph.edges)
        if (const auto it = geometry.edges.constFind(e.id); it != geometry.edges.cend())
            out += edgeSvg(e, *it);
    for (const LayoutNode &n : graph.nodes)
        if (const auto it = geometry.nodes.constFind(n.id); it != geometry.nodes.cend())
            out += nodeSvg(n, *it, hrefOf);
    return out + QStringLiteral("</svg>\n");
}

LayoutResult SiteDiagram::layout(const LayoutGraph &graph)
{
    // The GUI's helper process where there is one: Graphviz can abort() or run for minutes on
    // some graphs (seen on Autoware), which must cost one drawing, not the whole site.
    if (!GraphLayout::helperPath().isEmpty()) {
        LayoutOptions options;
        options.timeoutMs = kLayoutTimeoutMs;
        return GraphLayout::layout(graph, options);
    }
    return InProcessLayout::layout(graph);
}

SiteDiagram::Result SiteDiagram::draw(const Composite &composite, const QString &title,
                                      const QString &id,
                                      const std::function<QString(const QString &key)> &hrefOf)
{
    Result result;
    LayoutGraph graph = DiagramBuilder::build(composite);
    if (DiagramOverview::boxArea(graph) > kOverviewArea) {
        graph = DiagramBuilder::build(composite, DiagramOverview::options(composite, {}));
        result.overview = true;
    }
    LayoutResult layout = SiteDiagram::layout(graph);
    if (!layout.ok && !result.overview) {
        // Graphviz fails on some drawings (an assertion in its crossing minimisation, a
        // timeout): the overview often gets through where the full drawing did not.
        graph = DiagramBuilder::build(composite, DiagramOverview::options(composite, {}));
        result.overview = true;
        layout = SiteDiagram::layout(graph);
    }
    result.elements = int(graph.nodes.size());
    if (!layout.ok) {
        result.error =
            layout.error.isEmpty() ? tr("The diagram could not be laid out.") : layout.error;
        return result;
    }
    result.svg = svg(graph, layout.geometry, title, id, hrefOf);
    return result;
}

} // namespace rosarch
