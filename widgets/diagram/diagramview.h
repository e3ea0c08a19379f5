#pragma once

#include <QGraphicsView>

class QLabel;

namespace rosarch {

class DiagramMinimap;

/// The composed diagram's view: drag to pan, Ctrl+wheel and +/-/0 to zoom, and three overlays
/// on top of the drawing: a busy note, a message (errors, empty states) and a banner.
class DiagramView : public QGraphicsView
{
    Q_OBJECT
public:
    explicit DiagramView(QWidget *parent = nullptr);

    qreal zoom() const { return transform().m11(); }
    void setZoom(qreal zoom);
    void zoomIn();
    void zoomOut();
    /// Fits the whole diagram, never enlarging beyond 100 % nor shrinking below the legible
    /// zoom (the minimap then shows the rest).
    void fitDiagram();
    /// The zoom that would fit the whole diagram (at most 100 %), legible or not.
    qreal fitZoom() const;
    /// The zoom that would fit a diagram of `size` (scene units) in the viewport.
    qreal fitZoom(const QSizeF &size) const;
    /// The smallest zoom at which the diagram's text is still legible; Fit stops there.
    void setLegibleZoom(qreal zoom) { m_legibleZoom = zoom; }
    qreal legibleZoom() const { return m_legibleZoom; }
    DiagramMinimap *minimap() const { return m_minimap; }

    /// "Laying out…" while `text` is not empty.
    void setBusyText(const QString &text);
    QString busyText() const;
    /// A message in the middle of the view instead of a drawing ("" hides it).
    void setMessage(const QString &text);
    QString message() const;
    /// A note across the top of the view ("" hides it).
    void setBanner(const QString &text);
    QString banner() const;

Q_SIGNALS:
    void zoomChanged(qreal zoom);

protected:
    void wheelEvent(QWheelEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

private:
    void placeOverlays();

    QLabel *m_busy;
    QLabel *m_message;
    QLabel *m_banner;
    DiagramMinimap *m_minimap;
    qreal m_legibleZoom = 0;
};

} // namespace rosarch
