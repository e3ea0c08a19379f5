#pragma once

#include <QGraphicsView>

class QLabel;

namespace rosarch {

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
    /// Fits the whole diagram, never enlarging beyond 100 %.
    void fitDiagram();

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
};

} // namespace rosarch
