#include "widgets/diagram/diagramitem.h"
#include "widgets/diagram/diagramstyle.h"

#include <QPainter>

namespace rosarch {

namespace {
bool plainDrawing = false;
}

DiagramItem::DiagramItem(const QString &key, const DiagramStyle *style) : m_key(key), m_style(style)
{
    setFlag(ItemIsSelectable);
}

void DiagramItem::setMatched(bool matched)
{
    if (m_matched == matched)
        return;
    m_matched = matched;
    update();
}

void DiagramItem::setMark(DiagramMark mark)
{
    if (m_mark == mark)
        return;
    m_mark = mark;
    update();
}

void DiagramItem::setPlainDrawing(bool plain)
{
    plainDrawing = plain;
}

void DiagramItem::paintDecorations(QPainter *painter, const QPainterPath &outline) const
{
    painter->save();
    painter->setBrush(Qt::NoBrush);
    if (m_mark == DiagramMark::Extra) {
        painter->setPen(QPen(style().extra, 2.2, Qt::DashLine));
        painter->drawRoundedRect(outline.boundingRect().adjusted(-4, -4, 4, 4), 6, 6);
    }
    if (!plainDrawing && (isSelected() || m_matched)) {
        QColor c = isSelected() ? style().selection : style().match;
        c.setAlphaF(isSelected() ? 0.9 : 0.75);
        painter->setPen(QPen(c, isSelected() ? 3 : 4, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter->drawPath(outline);
    }
    painter->restore();
}

} // namespace rosarch
