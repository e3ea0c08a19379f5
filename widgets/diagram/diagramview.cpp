#include "widgets/diagram/diagramview.h"
#include "widgets/diagram/diagramminimap.h"
#include "widgets/diagram/diagramscene.h"

#include <QKeyEvent>
#include <QLabel>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace rosarch {

namespace {
constexpr qreal kMinZoom = 0.1;
constexpr qreal kMaxZoom = 4.0;
constexpr qreal kStep = 1.2;

QLabel *overlay(QWidget *parent, const QString &objectName)
{
    auto *label = new QLabel(parent);
    label->setObjectName(objectName);
    label->setWordWrap(true);
    label->setAlignment(Qt::AlignCenter);
    label->setAutoFillBackground(true);
    label->setMargin(10);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->hide();
    return label;
}
} // namespace

DiagramView::DiagramView(QWidget *parent)
    : QGraphicsView(parent), m_busy(overlay(this, QStringLiteral("diagramBusy"))),
      m_message(overlay(this, QStringLiteral("diagramMessage"))),
      m_banner(overlay(this, QStringLiteral("diagramBanner"))), m_minimap(new DiagramMinimap(this))
{
    setDragMode(ScrollHandDrag);
    setRenderHints(QPainter::Antialiasing | QPainter::TextAntialiasing |
                   QPainter::SmoothPixmapTransform);
    setTransformationAnchor(AnchorUnderMouse);
    setResizeAnchor(AnchorViewCenter);
    setViewportUpdateMode(SmartViewportUpdate);
    setFocusPolicy(Qt::StrongFocus);
    m_busy->setFrameShape(QFrame::StyledPanel);
    m_message->setForegroundRole(QPalette::PlaceholderText);
    m_message->setAutoFillBackground(false);
    m_banner->setFrameShape(QFrame::StyledPanel);
    m_banner->setAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    m_banner->setBackgroundRole(QPalette::ToolTipBase);
    m_banner->setForegroundRole(QPalette::ToolTipText);
}

void DiagramView::setZoom(qreal zoom)
{
    zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    if (qFuzzyCompare(zoom, this->zoom()))
        return;
    setTransform(QTransform::fromScale(zoom, zoom));
    m_minimap->updateVisibility();
    Q_EMIT zoomChanged(zoom);
}

void DiagramView::zoomIn()
{
    setZoom(zoom() * kStep);
}

void DiagramView::zoomOut()
{
    setZoom(zoom() / kStep);
}

void DiagramView::fitDiagram()
{
    const QRectF rect = sceneRect();
    if (rect.isEmpty())
        return;
    const qreal fit = fitZoom();
    setZoom(std::min(std::max(fit, m_legibleZoom), 1.0));
    if (fit >= zoom()) {
        centerOn(rect.center());
    } else { // too big to fit legibly: start where reading starts, at the top left
        const QSizeF visible = QSizeF(viewport()->size()) / zoom();
        QPointF corner = rect.topLeft();
        // Unless no part is in sight from there (a wide layout's corner can be empty frame,
        // or boundary ports only): then from the part nearest that corner.
        const auto *diagram = qobject_cast<const DiagramScene *>(scene());
        const QRectF first = diagram ? diagram->readingStart() : QRectF();
        if (!first.isNull() && !QRectF(corner, visible).contains(first)) {
            constexpr qreal kMargin = 24;
            corner = {std::clamp(first.left() - kMargin, rect.left(),
                                 std::max(rect.left(), rect.right() - visible.width())),
                      std::clamp(first.top() - kMargin, rect.top(),
                                 std::max(rect.top(), rect.bottom() - visible.height()))};
        }
        centerOn(corner.x() + visible.width() / 2, corner.y() + visible.height() / 2);
    }
    m_minimap->updateVisibility();
}

qreal DiagramView::fitZoom() const
{
    return fitZoom(sceneRect().size());
}

qreal DiagramView::fitZoom(const QSizeF &size) const
{
    if (size.isEmpty())
        return 1.0;
    const QSizeF available = viewport()->size() - QSizeF(4, 4);
    return std::min({available.width() / size.width(), available.height() / size.height(), 1.0});
}

void DiagramView::setBusyText(const QString &text)
{
    m_busy->setText(text);
    m_busy->setVisible(!text.isEmpty());
    placeOverlays();
}

QString DiagramView::busyText() const
{
    return m_busy->isVisibleTo(this) ? m_busy->text() : QString();
}

void DiagramView::setMessage(const QString &text)
{
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
    placeOverlays();
}

QString DiagramView::message() const
{
    return m_message->isVisibleTo(this) ? m_message->text() : QString();
}

void DiagramView::setBanner(const QString &text)
{
    m_banner->setText(text);
    m_banner->setToolTip(text);
    m_banner->setVisible(!text.isEmpty());
    placeOverlays();
}

QString DiagramView::banner() const
{
    return m_banner->isVisibleTo(this) ? m_banner->text() : QString();
}

void DiagramView::wheelEvent(QWheelEvent *event)
{
    if (!(event->modifiers() & Qt::ControlModifier)) {
        QGraphicsView::wheelEvent(event);
        return;
    }
    const int delta = event->angleDelta().y();
    if (delta != 0)
        setZoom(zoom() * std::pow(kStep, delta / 120.0));
    event->accept();
}

void DiagramView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Plus:
    case Qt::Key_Equal:
        zoomIn();
        return;
    case Qt::Key_Minus:
        zoomOut();
        return;
    case Qt::Key_0:
        fitDiagram();
        return;
    default:
        QGraphicsView::keyPressEvent(event);
    }
}

void DiagramView::resizeEvent(QResizeEvent *event)
{
    QGraphicsView::resizeEvent(event);
    placeOverlays();
}

void DiagramView::placeOverlays()
{
    const QRect area = viewport()->geometry();
    const int width = std::min(area.width() - 24, 460);
    for (QLabel *label : {m_busy, m_message}) {
        const int height = label->heightForWidth(width);
        label->setGeometry(area.left() + (area.width() - width) / 2,
                           area.top() + (area.height() - height) / 2, width, height);
    }
    const int bannerHeight = m_banner->heightForWidth(area.width() - 16);
    m_banner->setGeometry(area.left() + 8, area.top() + 8, area.width() - 16, bannerHeight);
    m_busy->raise();
    m_banner->raise();
}

} // namespace rosarch
