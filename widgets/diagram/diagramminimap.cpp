#include "widgets/diagram/diagramminimap.h"

#include <QEvent>
#include <QGraphicsScene>
#include <QGraphicsView>
#include <QMouseEvent>
#include <QPainter>
#include <QScrollBar>

#include <algorithm>

namespace rosarch {

DiagramMinimap::DiagramMinimap(QGraphicsView *view)
    : QWidget(view), m_view(view), m_viewport(view->viewport())
{
    setObjectName(QStringLiteral("diagramMinimap"));
    setCursor(Qt::PointingHandCursor);
    setToolTip(tr("The whole diagram: click or drag to move the view"));
    hide();
    view->installEventFilter(this);
    view->viewport()->installEventFilter(this); // scroll bars come and go: the viewport resizes
    for (QScrollBar *bar : {view->horizontalScrollBar(), view->verticalScrollBar()})
        connect(bar, &QScrollBar::valueChanged, this, [this] {
            updateVisibility();
            update();
        });
}

void DiagramMinimap::refresh()
{
    QGraphicsScene *scene = m_view->scene();
    m_sceneRect = scene ? scene->sceneRect() : QRectF();
    m_contentRect = scene ? scene->itemsBoundingRect() : QRectF();
    m_picture = {};
    if (scene && !m_sceneRect.isEmpty()) {
        QSizeF size = m_sceneRect.size();
        size.scale(kLongSide, kLongSide, Qt::KeepAspectRatio);
        const qreal ratio = devicePixelRatioF();
        m_picture = QPixmap((size * ratio).toSize().expandedTo(QSize(1, 1)));
        m_picture.setDevicePixelRatio(ratio);
        m_picture.fill(Qt::transparent);
        QPainter painter(&m_picture);
        painter.setRenderHint(QPainter::Antialiasing);
        scene->render(&painter, QRectF(QPointF(), size), m_sceneRect);
    }
    updateVisibility();
    update();
}

void DiagramMinimap::updateVisibility()
{
    const QRectF shown = m_view->mapToScene(m_view->viewport()->rect()).boundingRect();
    // The drawing, not the margin around it, decides.
    const bool fits = m_picture.isNull() || shown.adjusted(-1, -1, 1, 1).contains(m_contentRect);
    place();
    setVisible(!fits && m_cornerFree);
    if (isVisible())
        raise();
}

void DiagramMinimap::place()
{
    const QSizeF size =
        m_picture.isNull() ? QSizeF(kLongSide, kLongSide) : m_picture.deviceIndependentSize();
    const QRect area = m_view->viewport()->geometry();
    const QSize outer = size.toSize() + QSize(6, 6);
    const int left = area.left() + kMargin;
    const int right = area.right() - outer.width() - kMargin;
    const int top = area.top() + kMargin;
    const int bottom = area.bottom() - outer.height() - kMargin;
    // The kept-clear element as the view shows it, in the view's coordinates (as ours).
    const QRect clear =
        m_keepClear.isEmpty()
            ? QRect()
            : m_view->mapFromScene(m_keepClear).boundingRect().translated(area.topLeft());
    m_cornerFree = false;
    for (const QPoint &corner :
         {QPoint(right, bottom), QPoint(left, bottom), QPoint(right, top), QPoint(left, top)}) {
        const QRect at(corner, outer);
        if (clear.isEmpty() || !at.intersects(clear)) {
            setGeometry(at);
            m_cornerFree = true;
            return;
        }
    }
    setGeometry(right, bottom, outer.width(), outer.height());
}

void DiagramMinimap::setKeepClear(const QRectF &sceneRect)
{
    m_keepClear = sceneRect;
    updateVisibility();
}

QRectF DiagramMinimap::pictureRect() const
{
    return QRectF(QPointF(3, 3), m_picture.deviceIndependentSize());
}

QRectF DiagramMinimap::viewportRect() const
{
    if (m_sceneRect.isEmpty())
        return {};
    const QRectF shown = m_view->mapToScene(m_view->viewport()->rect()).boundingRect();
    const QRectF picture = pictureRect();
    const qreal sx = picture.width() / m_sceneRect.width();
    const qreal sy = picture.height() / m_sceneRect.height();
    const QRectF r(picture.left() + (shown.left() - m_sceneRect.left()) * sx,
                   picture.top() + (shown.top() - m_sceneRect.top()) * sy, shown.width() * sx,
                   shown.height() * sy);
    return r.intersected(picture);
}

QPointF DiagramMinimap::toScene(const QPointF &pos) const
{
    const QRectF picture = pictureRect();
    if (picture.isEmpty())
        return {};
    return {m_sceneRect.left() + (pos.x() - picture.left()) * m_sceneRect.width() / picture.width(),
            m_sceneRect.top() +
                (pos.y() - picture.top()) * m_sceneRect.height() / picture.height()};
}

void DiagramMinimap::centreAt(const QPointF &pos)
{
    m_view->centerOn(toScene(pos));
    update();
}

void DiagramMinimap::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    const QPalette &p = palette();
    painter.fillRect(rect(), p.color(QPalette::Base));
    painter.setPen(p.color(QPalette::Mid));
    painter.drawRect(rect().adjusted(0, 0, -1, -1));
    painter.drawPixmap(pictureRect().topLeft(), m_picture);
    QColor fill = p.color(QPalette::Highlight);
    fill.setAlpha(40);
    painter.setBrush(fill);
    painter.setPen(QPen(p.color(QPalette::Highlight), 1.5));
    painter.drawRect(viewportRect());
}

void DiagramMinimap::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton)
        centreAt(event->position());
    event->accept();
}

void DiagramMinimap::mouseMoveEvent(QMouseEvent *event)
{
    if (event->buttons() & Qt::LeftButton)
        centreAt(event->position());
    event->accept();
}

bool DiagramMinimap::eventFilter(QObject *watched, QEvent *event)
{
    // The type first, and the viewport as it was: while the view is being destroyed its
    // children still send events here, and it is no longer a QGraphicsView to ask.
    if ((event->type() == QEvent::Resize || event->type() == QEvent::Show) &&
        (watched == m_view || watched == m_viewport))
        updateVisibility();
    return QWidget::eventFilter(watched, event);
}

} // namespace rosarch
