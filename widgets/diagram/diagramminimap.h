#pragma once

#include <QPixmap>
#include <QWidget>

class QGraphicsView;

namespace rosarch {

/// A small picture of the whole diagram in a corner of the view, with the part the view shows
/// outlined; a click or a drag there moves the view. Hidden while the whole diagram fits.
class DiagramMinimap : public QWidget
{
    Q_OBJECT
public:
    /// Lives on `view` (not on its viewport, which scrolls its children).
    explicit DiagramMinimap(QGraphicsView *view);

    /// Draws the scene again (after a new layout or a style change) and shows or hides itself.
    void refresh();
    /// Shows or hides itself: shown when part of the diagram is outside the view.
    void updateVisibility();
    /// The view's visible area in minimap coordinates.
    QRectF viewportRect() const;
    /// The scene point under a minimap position.
    QPointF toScene(const QPointF &pos) const;
    /// Never covers this part of the scene (the current search match, the selection): the
    /// minimap takes the first corner of the view clear of it (bottom right, bottom left, top
    /// right, top left), or hides while none is. An empty rectangle frees every corner.
    void setKeepClear(const QRectF &sceneRect);
    QRectF keepClear() const { return m_keepClear; }

protected:
    void paintEvent(QPaintEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    static constexpr int kLongSide = 180;
    static constexpr int kMargin = 10;

    /// Takes the first corner clear of m_keepClear (m_cornerFree says whether there was one).
    void place();
    QRectF pictureRect() const; ///< where the scene is drawn inside the widget
    void centreAt(const QPointF &pos);

    QGraphicsView *m_view;
    QWidget *m_viewport; ///< the view's, kept: the filter must not ask a view being destroyed
    QPixmap m_picture;
    QRectF m_sceneRect;       ///< what m_picture shows
    QRectF m_contentRect;     ///< the drawing inside it, without the scene's margin
    QRectF m_keepClear;       ///< in scene coordinates
    bool m_cornerFree = true; ///< place() found a corner clear of m_keepClear
};

} // namespace rosarch
