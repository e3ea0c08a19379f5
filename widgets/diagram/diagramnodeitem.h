#pragma once

#include "diagram/layoutgraph.h"
#include "widgets/diagram/diagramitem.h"

namespace rosarch {

/// A laid-out node: a part with its port rows, a topic, service or action, a boundary port
/// on the frame, or a collapsed namespace. Positioned at its top-left corner.
class DiagramNodeItem : public DiagramItem
{
public:
    DiagramNodeItem(const LayoutNode &node, const DiagramStyle *style);

    const LayoutNode &node() const { return m_node; }
    /// Where an edge meets the port (scene coordinates).
    QPointF portScenePos(const QString &portId) const;
    /// Stretches a boundary port outwards so that it reaches the composite's frame.
    void setFrameExtension(qreal left, qreal right);
    /// The drawn body in item coordinates (the layout's box plus any frame extension).
    QRectF rect() const;

    QRectF boundingRect() const override;
    QPainterPath shape() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    QString keyAt(const QPointF &pos) const override;
    QString searchText() const override;

private:
    QPainterPath outline() const;
    QBrush fill() const;
    void paintPorts(QPainter *painter) const;
    void paintTexts(QPainter *painter) const;
    void paintOpenGlyph(QPainter *painter) const;
    QRectF portRow(const LayoutPort &port) const;

    LayoutNode m_node;
    qreal m_extendLeft = 0;
    qreal m_extendRight = 0;
};

} // namespace rosarch
