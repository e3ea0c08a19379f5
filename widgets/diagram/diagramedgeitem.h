#pragma once

#include "diagram/layoutgraph.h"
#include "widgets/diagram/diagramitem.h"

#include <QPainterPath>

namespace rosarch {

/// A laid-out edge: the layout's spline with an arrowhead, coloured by its kind.
class DiagramEdgeItem : public DiagramItem
{
public:
    DiagramEdgeItem(const LayoutEdge &edge, const EdgeGeometry &geometry,
                    const DiagramStyle *style);

    const LayoutEdge &edge() const { return m_edge; }
    QPainterPath path() const { return m_path; }

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;

private:
    LayoutEdge m_edge;
    QPainterPath m_path;
    QList<QPolygonF> m_arrows;
};

} // namespace rosarch
