#pragma once

#include "widgets/diagram/diagramitem.h"

namespace rosarch {

/// A frame with a label on top: a namespace cluster, an accepted subsystem (dashed, inside
/// its namespace), or the composite's own outer frame.
class DiagramClusterItem : public DiagramItem
{
public:
    enum class Kind
    {
        Namespace,
        Subsystem,
        Frame
    };

    DiagramClusterItem(Kind kind, const QString &key, const QRectF &rect, const QRectF &labelRect,
                       const QString &label, const QString &detail, const DiagramStyle *style);

    Kind kind() const { return m_kind; }
    QString label() const { return m_label; }

    QRectF boundingRect() const override;
    void paint(QPainter *painter, const QStyleOptionGraphicsItem *option, QWidget *widget) override;
    QString searchText() const override;

    /// The frame's tab on its top-left corner: the name, then the detail as it fits (the
    /// launch file's path, elided in the middle so the tab stays inside the frame).
    struct Tab
    {
        QString detail;
        qreal width = 0;
    };
    Tab tab() const;

private:
    Kind m_kind;
    QRectF m_rect;
    QRectF m_labelRect;
    QString m_label;
    QString m_detail;
};

} // namespace rosarch
