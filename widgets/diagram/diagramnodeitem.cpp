#include "widgets/diagram/diagramnodeitem.h"
#include "widgets/diagram/diagramstyle.h"

#include <QFontMetricsF>
#include <QPainter>

namespace rosarch {

namespace {
constexpr qreal kPortSquare = 8;
constexpr qreal kPortInset = 12; // as in DiagramBuilder
constexpr qreal kBoundarySquare = 10;

bool has(int flags, LayoutFlag flag)
{
    return flags & flag;
}

QFont italic(QFont f, bool on)
{
    f.setItalic(on);
    return f;
}
} // namespace

DiagramNodeItem::DiagramNodeItem(const LayoutNode &node, const DiagramStyle *style)
    : DiagramItem(node.key, style), m_node(node)
{
    setZValue(2);
}

QPointF DiagramNodeItem::portScenePos(const QString &portId) const
{
    return mapToScene(m_node.portAnchor(portId));
}

void DiagramNodeItem::setFrameExtension(qreal left, qreal right)
{
    prepareGeometryChange();
    m_extendLeft = std::max<qreal>(0, left);
    m_extendRight = std::max<qreal>(0, right);
}

QRectF DiagramNodeItem::rect() const
{
    return {-m_extendLeft, 0, m_node.width + m_extendLeft + m_extendRight, m_node.height};
}

QRectF DiagramNodeItem::boundingRect() const
{
    const qreal m = kDecorationMargin + kBoundarySquare / 2;
    return rect().adjusted(-m, -m, m, m);
}

QPainterPath DiagramNodeItem::shape() const
{
    QPainterPath p = outline();
    p.setFillRule(Qt::WindingFill); // the port squares overlap the box
    if (!m_node.ports.isEmpty())
        p.addRect(rect().adjusted(-kPortSquare / 2, 0, kPortSquare / 2, 0));
    return p;
}

QPainterPath DiagramNodeItem::outline() const
{
    const QRectF r = rect();
    QPainterPath p;
    switch (m_node.shape) {
    case LayoutNode::Shape::Ellipse:
        p.addEllipse(r);
        break;
    case LayoutNode::Shape::Hexagon: {
        // Graphviz's hexagon stretched to the box, so that edges end on its border.
        const qreal w = r.width();
        const qreal h = r.height();
        p.addPolygon(QPolygonF({{0, h / 2},
                                {w / 4, 0},
                                {3 * w / 4, 0},
                                {w, h / 2},
                                {3 * w / 4, h},
                                {w / 4, h},
                                {0, h / 2}}));
        break;
    }
    case LayoutNode::Shape::Queue: {
        // A horizontal cylinder: the queue of the PlantUML notation.
        const qreal rx = std::min<qreal>(7, r.width() / 6);
        p.moveTo(rx, 0);
        p.lineTo(r.width() - rx, 0);
        p.arcTo(QRectF(r.width() - 2 * rx, 0, 2 * rx, r.height()), 90, -180);
        p.lineTo(rx, r.height());
        p.arcTo(QRectF(0, 0, 2 * rx, r.height()), 270, -180);
        p.closeSubpath();
        break;
    }
    case LayoutNode::Shape::Folder: {
        const qreal tab = 9;
        const qreal tabWidth = std::min<qreal>(r.width() * 0.45, 70);
        p.moveTo(0, tab + 3);
        p.lineTo(0, 3);
        p.quadTo(0, 0, 3, 0);
        p.lineTo(tabWidth - 6, 0);
        p.lineTo(tabWidth, tab);
        p.lineTo(r.width() - 3, tab);
        p.quadTo(r.width(), tab, r.width(), tab + 3);
        p.lineTo(r.width(), r.height() - 3);
        p.quadTo(r.width(), r.height(), r.width() - 3, r.height());
        p.lineTo(3, r.height());
        p.quadTo(0, r.height(), 0, r.height() - 3);
        p.closeSubpath();
        break;
    }
    case LayoutNode::Shape::Tag:
        p.addRoundedRect(r, 4, 4);
        break;
    case LayoutNode::Shape::Box:
        p.addRoundedRect(r, 7, 7);
        break;
    }
    return p;
}

QBrush DiagramNodeItem::fill() const
{
    const DiagramStyle &s = style();
    switch (m_node.shape) {
    case LayoutNode::Shape::Queue:
        return s.topicFill;
    case LayoutNode::Shape::Ellipse:
        return s.serviceFill;
    case LayoutNode::Shape::Hexagon:
        return s.actionFill;
    case LayoutNode::Shape::Tag:
        return s.boundaryFill;
    case LayoutNode::Shape::Folder:
        return s.clusterFill;
    case LayoutNode::Shape::Box:
        break;
    }
    if (has(m_node.flags, LayoutInactive))
        return s.paper;
    // Only included launch files are openable or external.
    return has(m_node.flags, LayoutOpenable) || has(m_node.flags, LayoutExternal) ? s.launchFill
                                                                                  : s.partFill;
}

void DiagramNodeItem::paint(QPainter *painter, const QStyleOptionGraphicsItem *, QWidget *)
{
    const DiagramStyle &s = style();
    const bool inactive = has(m_node.flags, LayoutInactive);
    const QPainterPath path = outline();
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    if (inactive)
        painter->setOpacity(0.55);
    QPen border(s.partBorder, m_node.shape == LayoutNode::Shape::Box ? 1.3 : 1.1);
    if (inactive || has(m_node.flags, LayoutExternal))
        border.setStyle(Qt::DashLine);
    // What a person corrected (or accepted from a suggestion) has a quiet tinted dashed border.
    if (has(m_node.flags, LayoutCorrected) || has(m_node.flags, LayoutSuggested)) {
        border.setColor(s.corrected);
        border.setStyle(has(m_node.flags, LayoutCorrected) ? Qt::DashLine : Qt::DotLine);
        border.setWidthF(1.6);
    }
    painter->setPen(border);
    painter->setBrush(fill());
    painter->drawPath(path);
    if (m_node.shape == LayoutNode::Shape::Queue) { // the cylinder's near end
        const qreal rx = std::min<qreal>(7, m_node.width / 6);
        painter->setBrush(Qt::NoBrush);
        painter->drawArc(QRectF(m_node.width - 2 * rx, 0, 2 * rx, m_node.height), 90 * 16,
                         180 * 16);
    }
    paintTexts(painter);
    if (!m_node.ports.isEmpty())
        paintPorts(painter);
    if (m_node.shape == LayoutNode::Shape::Tag) { // the port on the composite's frame
        const qreal x = m_node.rank == LayoutNode::Rank::Sink ? rect().right() : rect().left();
        painter->setPen(QPen(s.frame, 1.3));
        painter->setBrush(s.partBorder);
        painter->drawRect(QRectF(x - kBoundarySquare / 2, m_node.height / 2 - kBoundarySquare / 2,
                                 kBoundarySquare, kBoundarySquare));
    }
    if (has(m_node.flags, LayoutOpenable))
        paintOpenGlyph(painter);
    if (has(m_node.flags, LayoutReviewed)) { // a small tick in the top-left corner
        painter->setPen(QPen(s.corrected, 1.6, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        painter->setBrush(Qt::NoBrush);
        const QPointF o = m_node.shape == LayoutNode::Shape::Box
                              ? QPointF(7, 7)
                              : QPointF(rect().width() / 2 - 4, 2);
        painter->drawPolyline(QPolygonF({o + QPointF(0, 4), o + QPointF(3, 7), o + QPointF(8, 0)}));
    }
    painter->restore();
    paintDecorations(painter, path);
}

void DiagramNodeItem::paintTexts(QPainter *painter) const
{
    const DiagramStyle &s = style();
    const bool box = m_node.shape == LayoutNode::Shape::Box;
    const bool folder = m_node.shape == LayoutNode::Shape::Folder;
    // A boundary port's label is its name: in italics when the name rests on a guess.
    const QFont labelFont = box || folder
                                ? s.titleFont
                                : italic(s.textFont, m_node.shape == LayoutNode::Shape::Tag &&
                                                         has(m_node.flags, LayoutUnresolved));
    const QFontMetricsF lm(labelFont);
    const QFontMetricsF dm(s.smallFont);
    QRectF area = rect();
    if (folder)
        area.setTop(9);
    qreal top;
    if (box) {
        top = 8;
    } else {
        const qreal total = lm.height() + (m_node.detail.isEmpty() ? 0 : dm.height());
        top = area.top() + (area.height() - total) / 2;
    }
    // Keep a boundary's text clear of its square, and an include's title of its open sign.
    const qreal inset = m_node.shape == LayoutNode::Shape::Tag ? kBoundarySquare
                        : has(m_node.flags, LayoutOpenable)    ? 22
                                                               : 6;
    QRectF line(area.left() + inset, top, area.width() - 2 * inset, lm.height());
    painter->setPen(s.text);
    painter->setFont(labelFont);
    painter->drawText(line, Qt::AlignCenter,
                      lm.elidedText(m_node.label, Qt::ElideMiddle, line.width()));
    if (m_node.detail.isEmpty())
        return;
    line = QRectF(line.left(), line.bottom(), line.width(), dm.height());
    painter->setPen(s.mutedText);
    painter->setFont(italic(s.smallFont, has(m_node.flags, LayoutUnresolved) &&
                                             m_node.shape != LayoutNode::Shape::Tag));
    painter->drawText(line, Qt::AlignCenter,
                      dm.elidedText(m_node.detail, Qt::ElideMiddle, line.width()));
    if (box && !m_node.ports.isEmpty()) {
        painter->setPen(QPen(s.partBorder, 0.6));
        painter->setOpacity(painter->opacity() * 0.5);
        const qreal y = m_node.headerHeight - 3;
        painter->drawLine(QPointF(6, y), QPointF(m_node.width - 6, y));
        painter->setOpacity(painter->opacity() * 2);
    }
}

void DiagramNodeItem::paintPorts(QPainter *painter) const
{
    const DiagramStyle &s = style();
    const QFontMetricsF fm(s.smallFont);
    for (const LayoutPort &port : m_node.ports) {
        const QPointF anchor = m_node.portAnchor(port.id);
        const bool inactive = has(port.flags, LayoutInactive);
        const bool corrected = has(port.flags, LayoutCorrected) || has(port.flags, LayoutSuggested);
        painter->setPen(QPen(corrected ? s.corrected : s.partBorder, corrected ? 1.5 : 1.1,
                             inactive ? Qt::DotLine : Qt::SolidLine));
        painter->setBrush(inactive ? s.paper : corrected ? s.corrected : s.portFill);
        painter->drawRect(QRectF(anchor.x() - kPortSquare / 2, anchor.y() - kPortSquare / 2,
                                 kPortSquare, kPortSquare));
        if (has(port.flags, LayoutParameterDerived)) { // the name comes from a parameter
            painter->setBrush(s.partBorder);
            painter->setPen(Qt::NoPen);
            painter->drawEllipse(anchor, 1.8, 1.8);
        }
        const qreal width = m_node.width / 2 - kPortInset - 4;
        const QRectF text =
            port.input ? QRectF(kPortInset, anchor.y() - fm.height() / 2, width, fm.height())
                       : QRectF(m_node.width - kPortInset - width, anchor.y() - fm.height() / 2,
                                width, fm.height());
        painter->setFont(italic(s.smallFont, has(port.flags, LayoutUnresolved)));
        painter->setPen(inactive ? s.mutedText : s.text);
        const QString label =
            fm.elidedText(port.label, Qt::ElideMiddle, m_node.width - 2 * kPortInset);
        painter->drawText(text,
                          (port.input ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter |
                              Qt::TextDontClip,
                          label);
    }
}

void DiagramNodeItem::paintOpenGlyph(QPainter *painter) const
{
    // A small "opens in its own diagram" sign in the top-right corner.
    const QRectF r(m_node.width - 17, 7, 10, 10);
    painter->setPen(QPen(style().partBorder, 1.1));
    painter->setBrush(Qt::NoBrush);
    painter->drawRect(r.adjusted(0, 3, -3, 0));
    painter->drawRect(r.adjusted(3, 0, 0, -3));
}

QRectF DiagramNodeItem::portRow(const LayoutPort &port) const
{
    const QPointF anchor = m_node.portAnchor(port.id);
    const qreal half = m_node.rowHeight / 2;
    return port.input ? QRectF(-kPortSquare, anchor.y() - half, m_node.width / 2 + kPortSquare,
                               m_node.rowHeight)
                      : QRectF(m_node.width / 2, anchor.y() - half, m_node.width / 2 + kPortSquare,
                               m_node.rowHeight);
}

QString DiagramNodeItem::keyAt(const QPointF &pos) const
{
    for (const LayoutPort &port : m_node.ports)
        if (portRow(port).contains(pos))
            return port.key;
    return key();
}

QString DiagramNodeItem::searchText() const
{
    return m_node.label;
}

} // namespace rosarch
