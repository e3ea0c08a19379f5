#include "widgets/diagram/diagramedgeitem.h"
#include "widgets/diagram/diagramstyle.h"

#include <QPainter>
#include <QPainterPathStroker>
#include <QtMath>

namespace rosarch {

namespace {
constexpr qreal kPortHalf = 4; // half a port square (DiagramNodeItem)

/// An arrowhead with its tip at `tip`, pointing away from `from`.
QPolygonF arrowHead(const QPointF &from, const QPointF &tip)
{
    const QLineF line(tip, from);
    if (line.length() < 0.1)
        return {};
    const qreal angle = qDegreesToRadians(line.angle());
    const qreal length = 9;
    const qreal spread = 0.42;
    const auto corner = [&](qreal a) {
        return tip + QPointF(std::cos(a) * length, -std::sin(a) * length);
    };
    return QPolygonF({tip, corner(angle + spread), corner(angle - spread), tip});
}
} // namespace

DiagramEdgeItem::DiagramEdgeItem(const LayoutEdge &edge, const EdgeGeometry &geometry,
                                 const DiagramStyle *style)
    : DiagramItem(edge.key, style), m_edge(edge)
{
    setZValue(1);
    const QList<QPointF> &p = geometry.points;
    if (p.isEmpty())
        return;
    m_path.moveTo(p.first());
    for (int i = 1; i + 2 < p.size(); i += 3)
        m_path.cubicTo(p[i], p[i + 1], p[i + 2]);
    // Graphviz stops the spline where an arrowhead begins. A reversed (back) edge keeps its
    // points from head to tail and flags the arrow at the start instead of the end.
    // An arrow into a port stops at the port's square, which sits across the box's edge.
    const auto tip = [&edge](const QPointF &from, const QPointF &to) {
        const QLineF line(from, to);
        if (edge.headPort.isEmpty() || line.length() <= kPortHalf)
            return to;
        return line.pointAt((line.length() - kPortHalf) / line.length());
    };
    if (geometry.hasArrowEnd) {
        const QPointF end = tip(p.last(), geometry.arrowEnd);
        m_path.lineTo(end);
        m_arrows << arrowHead(p.last(), end);
    }
    if (geometry.hasArrowStart) {
        const QPointF start = tip(p.first(), geometry.arrowStart);
        QPainterPath head(start);
        head.lineTo(p.first());
        m_path.addPath(head);
        m_arrows << arrowHead(p.first(), start);
    }
}

QRectF DiagramEdgeItem::boundingRect() const
{
    QRectF r = m_path.boundingRect();
    for (const QPolygonF &arrow : m_arrows)
        r = r.united(arrow.boundingRect());
    return r.adjusted(-8, -8, 8, 8);
}

QPainterPath DiagramEdgeItem::shape() const
{
    QPainterPathStroker stroker;
    stroker.setWidth(9);
    QPainterPath p = stroker.createStroke(m_path);
    for (const QPolygonF &arrow : m_arrows)
        p.addPolygon(arrow);
    return p;
}

void DiagramEdgeItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const QColor color = style().edgeColor(m_edge.category);
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    if (m_edge.flags & LayoutInactive)
        painter->setOpacity(0.45);
    const qreal width = isSelected() ? 2.6 : 1.6;
    QPen pen(color, width, m_edge.dashed ? Qt::DashLine : Qt::SolidLine, Qt::RoundCap,
             Qt::RoundJoin);
    if (m_edge.dashed)
        pen.setDashPattern({4, 3});
    painter->setPen(pen);
    painter->setBrush(Qt::NoBrush);
    painter->drawPath(m_path);
    painter->setPen(QPen(color, 1, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    painter->setBrush(color);
    for (const QPolygonF &arrow : m_arrows)
        painter->drawPolygon(arrow);
    painter->restore();
    if (isSelected() || isMatched() || mark() != DiagramMark::None)
        paintDecorations(painter, m_path);
}

} // namespace rosarch
