#pragma once

#include "diagram/layoutgraph.h"
#include "widgets/diagram/diagramitem.h"
#include "widgets/diagram/diagramstyle.h"

#include <QGraphicsScene>
#include <QHash>

namespace rosarch {

/// The drawing of one laid-out composite: a frame, namespace clusters, nodes and edges, each
/// item keyed back to the model. Reports clicks as element keys; exports itself.
class DiagramScene : public QGraphicsScene
{
    Q_OBJECT
public:
    explicit DiagramScene(QObject *parent = nullptr);

    void setDiagramStyle(const DiagramStyle &style);
    const DiagramStyle &diagramStyle() const { return m_style; }

    /// Replaces the drawing with `graph` at `geometry`, in a frame titled `title`.
    void setDiagram(const LayoutGraph &graph, const LayoutGeometry &geometry, const QString &title,
                    const QString &detail);
    void clearDiagram();
    /// The scene rectangle setDiagram gives a layout of `bounds`: the frame and a margin.
    static QRectF sceneRectFor(const QRectF &bounds);
    bool isEmpty() const { return m_items.isEmpty(); }

    /// The item drawing an element ("part:part1", ...), or null.
    DiagramItem *item(const QString &key) const { return m_items.value(key); }
    /// The keys of all drawn elements, sorted.
    QStringList keys() const;
    /// The frame around the whole diagram (scene coordinates).
    QRectF frameRect() const { return m_frame; }
    /// Where reading starts: the part nearest the frame's top left corner, else the box nearest
    /// it (scene coordinates; null without boxes). A wide layout can leave that corner itself
    /// empty, or hold only boundary ports.
    QRectF readingStart() const;

    /// Comparison marks by element key; elements not named lose their mark.
    void setMarks(const QHash<QString, DiagramMark> &marks);
    /// Keys of the elements whose name contains `text` (case-insensitive), top to bottom.
    QStringList find(const QString &text) const;
    /// Shows the search matches; the others lose their match mark.
    void setMatches(const QStringList &keys);
    /// Tooltips by element key (ports included).
    void setToolTips(const QHash<QString, QString> &toolTips) { m_toolTips = toolTips; }
    QString toolTip(const QString &key) const { return m_toolTips.value(key); }

    /// Selects an element besides the current selection, and keeps it selected when the click
    /// in progress (which selects only the clicked item on release) ends.
    void selectAlso(const QString &key);

    /// The key of the element under a scene position ("" for none).
    QString keyAt(const QPointF &scenePos) const;

    /// Writes the whole diagram in the light style (for documentation).
    bool exportSvg(const QString &path, const QString &title);
    bool exportPng(const QString &path, qreal scale = 2);

Q_SIGNALS:
    void elementClicked(const QString &key);
    void elementDoubleClicked(const QString &key);
    void elementContextMenuRequested(const QString &key, const QPoint &screenPos);

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent *event) override;
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent *event) override;
    void contextMenuEvent(QGraphicsSceneContextMenuEvent *event) override;
    void helpEvent(QGraphicsSceneHelpEvent *event) override;

private:
    void renderForExport(QPainter *painter, const QRectF &target);

    DiagramStyle m_style;
    QHash<QString, DiagramItem *> m_items;
    QHash<QString, QString> m_toolTips;
    QRectF m_frame;
    bool m_pressed = false;
    QStringList m_alsoSelected; ///< selected by selectAlso during the click in progress
};

} // namespace rosarch
