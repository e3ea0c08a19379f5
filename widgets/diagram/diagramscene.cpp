#include "widgets/diagram/diagramscene.h"
#include "diagram/diagrambuilder.h"
#include "widgets/diagram/diagramclusteritem.h"
#include "widgets/diagram/diagramedgeitem.h"
#include "widgets/diagram/diagramnodeitem.h"

#include <QGraphicsSceneContextMenuEvent>
#include <QGraphicsSceneHelpEvent>
#include <QGraphicsSceneMouseEvent>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>
#include <QToolTip>

namespace rosarch {

namespace {
constexpr qreal kFrameMargin = 24;
constexpr qreal kTitleSpace = 36;
constexpr qreal kSceneMargin = 16;
} // namespace

DiagramScene::DiagramScene(QObject *parent)
    : QGraphicsScene(parent), m_style(DiagramStyle::make(false))
{
}

void DiagramScene::setDiagramStyle(const DiagramStyle &style)
{
    m_style = style; // items paint from this object
    setBackgroundBrush(m_style.paper);
    update();
}

void DiagramScene::clearDiagram()
{
    clear();
    m_items.clear();
    m_toolTips.clear();
    m_frame = {};
    setSceneRect(QRectF());
}

void DiagramScene::setDiagram(const LayoutGraph &graph, const LayoutGeometry &geometry,
                              const QString &title, const QString &detail)
{
    clearDiagram();
    const QRectF bounds = geometry.bounds;
    m_frame = bounds.adjusted(-kFrameMargin, -kTitleSpace - 8, kFrameMargin, kFrameMargin);
    auto *frame = new DiagramClusterItem(DiagramClusterItem::Kind::Frame, QStringLiteral("frame"),
                                         m_frame, {}, title, detail, &m_style);
    addItem(frame);

    for (const LayoutCluster &c : graph.clusters) {
        if (!geometry.clusters.contains(c.id))
            continue;
        int depth = 0;
        for (const LayoutCluster *p = graph.cluster(c.parent); p; p = graph.cluster(p->parent))
            ++depth;
        const bool subsystem = DiagramKey::parse(c.key).kind == DiagramKey::Kind::Subsystem;
        auto *item = new DiagramClusterItem(
            subsystem ? DiagramClusterItem::Kind::Subsystem : DiagramClusterItem::Kind::Namespace,
            c.key, geometry.clusters.value(c.id), geometry.clusterLabels.value(c.id), c.label, {},
            &m_style);
        item->setZValue(-1 + depth * 0.01);
        addItem(item);
        m_items.insert(c.key, item);
    }
    for (const LayoutNode &n : graph.nodes) {
        auto *item = new DiagramNodeItem(n, &m_style);
        // Centred where the layout put it (Graphviz rounds sizes to hundredths of an inch).
        item->setPos(geometry.nodes.value(n.id).center() - QPointF(n.width / 2, n.height / 2));
        // Boundary ports reach out to the frame, their squares on its line: other nodes may
        // share the outermost column, so the frame cannot simply run through the ports.
        if (n.rank == LayoutNode::Rank::Source)
            item->setFrameExtension(item->x() - m_frame.left(), 0);
        else if (n.rank == LayoutNode::Rank::Sink)
            item->setFrameExtension(0, m_frame.right() - item->x() - n.width);
        addItem(item);
        m_items.insert(n.key, item);
    }
    for (const LayoutEdge &e : graph.edges) {
        if (!geometry.edges.contains(e.id))
            continue;
        auto *item = new DiagramEdgeItem(e, geometry.edges.value(e.id), &m_style);
        addItem(item);
        m_items.insert(e.key, item);
    }
    setSceneRect(sceneRectFor(bounds));
}

QRectF DiagramScene::sceneRectFor(const QRectF &bounds)
{
    return bounds.adjusted(-kFrameMargin - kSceneMargin, -kTitleSpace - 8 - kSceneMargin,
                           kFrameMargin + kSceneMargin, kFrameMargin + kSceneMargin);
}

QRectF DiagramScene::readingStart() const
{
    // A part (a node, an include) before any other box: the boundary boxes of a system that
    // does not fit stand at its left edge, far from its nodes.
    QRectF best;
    qreal bestDistance = 0;
    bool bestIsPart = false;
    for (auto it = m_items.cbegin(); it != m_items.cend(); ++it) {
        if (!dynamic_cast<const DiagramNodeItem *>(it.value()))
            continue;
        const bool part = it.key().startsWith(QLatin1String("part:"));
        const QRectF r = it.value()->sceneBoundingRect();
        const qreal distance = QLineF(m_frame.topLeft(), r.topLeft()).length();
        if (best.isNull() || (part && !bestIsPart) ||
            (part == bestIsPart && distance < bestDistance)) {
            best = r;
            bestDistance = distance;
            bestIsPart = part;
        }
    }
    return best;
}

QStringList DiagramScene::keys() const
{
    QStringList k = m_items.keys();
    k.sort();
    return k;
}

void DiagramScene::setMarks(const QHash<QString, DiagramMark> &marks)
{
    for (auto it = m_items.cbegin(); it != m_items.cend(); ++it)
        it.value()->setMark(marks.value(it.key(), DiagramMark::None));
}

QStringList DiagramScene::find(const QString &text) const
{
    const QString needle = text.trimmed();
    if (needle.isEmpty())
        return {};
    QList<DiagramItem *> hits;
    for (DiagramItem *item : m_items)
        if (item->searchText().contains(needle, Qt::CaseInsensitive))
            hits << item;
    std::sort(hits.begin(), hits.end(), [](DiagramItem *a, DiagramItem *b) {
        const QPointF pa = a->sceneBoundingRect().center();
        const QPointF pb = b->sceneBoundingRect().center();
        if (!qFuzzyCompare(pa.y(), pb.y()))
            return pa.y() < pb.y();
        if (!qFuzzyCompare(pa.x(), pb.x()))
            return pa.x() < pb.x();
        return a->key() < b->key();
    });
    QStringList out;
    for (DiagramItem *item : std::as_const(hits))
        out << item->key();
    return out;
}

void DiagramScene::setMatches(const QStringList &keys)
{
    for (auto it = m_items.cbegin(); it != m_items.cend(); ++it)
        it.value()->setMatched(keys.contains(it.key()));
}

QString DiagramScene::keyAt(const QPointF &scenePos) const
{
    for (QGraphicsItem *item : items(scenePos, Qt::IntersectsItemShape, Qt::DescendingOrder)) {
        auto *d = dynamic_cast<DiagramItem *>(item);
        if (d && m_items.value(d->key()) == d)
            return d->keyAt(d->mapFromScene(scenePos));
    }
    return {};
}

void DiagramScene::selectAlso(const QString &key)
{
    if (DiagramItem *d = m_items.value(key)) {
        d->setSelected(true);
        if (m_pressed)
            m_alsoSelected << key;
    }
}

void DiagramScene::mousePressEvent(QGraphicsSceneMouseEvent *event)
{
    QGraphicsScene::mousePressEvent(event);
    if (event->button() != Qt::LeftButton)
        return;
    m_pressed = true;
    m_alsoSelected.clear();
    const QString key = keyAt(event->scenePos());
    if (!key.isEmpty())
        Q_EMIT elementClicked(key);
}

void DiagramScene::mouseReleaseEvent(QGraphicsSceneMouseEvent *event)
{
    QGraphicsScene::mouseReleaseEvent(event);
    if (event->button() != Qt::LeftButton)
        return;
    m_pressed = false;
    for (const QString &key : std::as_const(m_alsoSelected))
        if (DiagramItem *d = m_items.value(key))
            d->setSelected(true);
    m_alsoSelected.clear();
}

void DiagramScene::mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event)
{
    QGraphicsScene::mouseDoubleClickEvent(event);
    const QString key = keyAt(event->scenePos());
    if (!key.isEmpty())
        Q_EMIT elementDoubleClicked(key);
}

void DiagramScene::contextMenuEvent(QGraphicsSceneContextMenuEvent *event)
{
    const QString key = keyAt(event->scenePos());
    if (key.isEmpty())
        return;
    event->accept();
    Q_EMIT elementContextMenuRequested(key, event->screenPos());
}

void DiagramScene::helpEvent(QGraphicsSceneHelpEvent *event)
{
    const QString text = m_toolTips.value(keyAt(event->scenePos()));
    if (text.isEmpty()) {
        QToolTip::hideText();
        event->ignore();
        return;
    }
    QToolTip::showText(event->screenPos(), text, event->widget());
    event->accept();
}

void DiagramScene::renderForExport(QPainter *painter, const QRectF &target)
{
    // Documentation gets light paper and no selection or search marks, whatever the screen shows.
    const DiagramStyle screen = m_style;
    m_style = DiagramStyle::make(false);
    DiagramItem::setPlainDrawing(true);
    const QBrush background = backgroundBrush();
    setBackgroundBrush(m_style.paper);
    render(painter, target, sceneRect());
    setBackgroundBrush(background);
    DiagramItem::setPlainDrawing(false);
    m_style = screen;
    update();
}

bool DiagramScene::exportSvg(const QString &path, const QString &title)
{
    if (m_items.isEmpty())
        return false;
    const QRectF source = sceneRect();
    QSvgGenerator svg;
    svg.setFileName(path);
    svg.setTitle(title);
    svg.setDescription(tr("Composed diagram exported by rosarch"));
    svg.setSize(source.size().toSize());
    svg.setViewBox(QRectF(QPointF(0, 0), source.size()));
    QPainter painter;
    if (!painter.begin(&svg))
        return false;
    renderForExport(&painter, QRectF(QPointF(0, 0), source.size()));
    return painter.end();
}

bool DiagramScene::exportPng(const QString &path, qreal scale)
{
    if (m_items.isEmpty())
        return false;
    // Large diagrams stay below 8000 px a side (about 250 MB of pixels at most).
    const QSizeF natural = sceneRect().size();
    scale = std::min(scale, 8000 / std::max(natural.width(), natural.height()));
    const QSizeF size = natural * scale;
    QImage image(size.toSize(), QImage::Format_ARGB32_Premultiplied);
    if (image.isNull())
        return false;
    image.fill(Qt::white);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setRenderHint(QPainter::TextAntialiasing);
    renderForExport(&painter, QRectF(QPointF(0, 0), size));
    painter.end();
    return image.save(path, "PNG");
}

} // namespace rosarch
