#include "widgets/diagram/diagramclusteritem.h"
#include "widgets/diagram/diagramstyle.h"

#include <QFontMetricsF>
#include <QPainter>

namespace rosarch {

DiagramClusterItem::DiagramClusterItem(Kind kind, const QString &key, const QRectF &rect,
                                       const QRectF &labelRect, const QString &label,
                                       const QString &detail, const DiagramStyle *style)
    : DiagramItem(key, style), m_kind(kind), m_rect(rect), m_labelRect(labelRect), m_label(label),
      m_detail(detail)
{
    setZValue(kind == Kind::Frame ? -2 : -1);
    if (kind == Kind::Frame)
        setFlag(ItemIsSelectable, false);
}

QRectF DiagramClusterItem::boundingRect() const
{
    return m_rect.adjusted(-kDecorationMargin, -kDecorationMargin, kDecorationMargin,
                           kDecorationMargin);
}

DiagramClusterItem::Tab DiagramClusterItem::tab() const
{
    const QFontMetricsF fm(style().titleFont);
    const QFontMetricsF dm(style().smallFont);
    // The detail gives way when the frame is narrower than the whole tab would be.
    const qreal room = m_rect.width() - fm.horizontalAdvance(m_label) - 30;
    Tab t;
    if (room > dm.horizontalAdvance(QStringLiteral("…")) * 2)
        t.detail = dm.elidedText(m_detail, Qt::ElideMiddle, room);
    t.width = fm.horizontalAdvance(m_label) + dm.horizontalAdvance(t.detail) + 30;
    return t;
}

void DiagramClusterItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const DiagramStyle &s = style();
    const bool frame = m_kind == Kind::Frame;
    QPainterPath outline;
    outline.addRoundedRect(m_rect, frame ? 4 : 9, frame ? 4 : 9);
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    if (m_kind == Kind::Subsystem) {
        // Dashed and unfilled: a grouping a person chose, not a scope the launch files make,
        // so the namespace's fill shows through.
        QPen pen(s.clusterBorder, 1.4, Qt::DashLine);
        pen.setDashPattern({5, 3});
        painter->setPen(pen);
        painter->setBrush(Qt::NoBrush);
    } else {
        painter->setPen(QPen(frame ? s.frame : s.clusterBorder, frame ? 1.6 : 1.1));
        painter->setBrush(frame ? s.frameFill : s.clusterFill);
    }
    painter->drawPath(outline);

    const QFont labelFont = frame ? s.titleFont : s.textFont;
    const QFontMetricsF fm(labelFont);
    QRectF line = m_labelRect;
    if (frame) {
        // The composite's name plus what it is, in a tab on the top-left corner.
        const QFontMetricsF dm(s.smallFont);
        const auto [detail, width] = this->tab();
        const QRectF tab(m_rect.left(), m_rect.top(), width, fm.height() + 10);
        QPainterPath tabPath;
        tabPath.moveTo(tab.bottomLeft());
        tabPath.lineTo(tab.right() - 8, tab.bottom());
        tabPath.lineTo(tab.right(), tab.bottom() - 8);
        tabPath.lineTo(tab.topRight());
        painter->setBrush(Qt::NoBrush);
        painter->drawPath(tabPath);
        line =
            QRectF(tab.left() + 8, tab.top() + 5, fm.horizontalAdvance(m_label) + 2, fm.height());
        painter->setFont(labelFont);
        painter->setPen(s.text);
        painter->drawText(line, Qt::AlignLeft | Qt::AlignVCenter, m_label);
        painter->setFont(s.smallFont);
        painter->setPen(s.mutedText);
        painter->drawText(
            QRectF(line.right() + 6, line.top(), dm.horizontalAdvance(detail) + 2, line.height()),
            Qt::AlignLeft | Qt::AlignVCenter, detail);
    } else {
        if (line.isEmpty())
            line = QRectF(m_rect.left() + 8, m_rect.top() + 4, m_rect.width() - 16, fm.height());
        line.moveLeft(m_rect.left() + 8);
        QFont font = labelFont;
        font.setItalic(m_kind == Kind::Subsystem);
        painter->setFont(font);
        painter->setPen(m_kind == Kind::Subsystem ? s.text : s.mutedText);
        painter->drawText(line.adjusted(0, 0, 40, 0), Qt::AlignLeft | Qt::AlignVCenter,
                          fm.elidedText(m_label, Qt::ElideMiddle, m_rect.width() - 16));
    }
    painter->restore();
    if (!frame)
        paintDecorations(painter, outline);
}

QString DiagramClusterItem::searchText() const
{
    return m_kind == Kind::Frame ? QString() : m_label;
}

} // namespace rosarch
