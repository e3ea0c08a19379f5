#pragma once

#include <QGraphicsItem>
#include <QString>

namespace rosarch {

struct DiagramStyle;

/// How a reference-model comparison marks an element of the diagram.
enum class DiagramMark
{
    None,
    Extra, ///< recovered but not in the reference: a red dashed outline
};

/// An element of the composed diagram that knows its key back to the model ("part:part1",
/// "channel:q_x", ...) and draws the selection, search-match and comparison marks.
class DiagramItem : public QGraphicsItem
{
public:
    DiagramItem(const QString &key, const DiagramStyle *style);

    QString key() const { return m_key; }
    /// The key of the element at a point in item coordinates (a port of a part, say).
    virtual QString keyAt(const QPointF &) const { return m_key; }
    /// The text that search matches ("" = not searchable).
    virtual QString searchText() const { return {}; }

    void setMatched(bool matched);
    bool isMatched() const { return m_matched; }
    void setMark(DiagramMark mark);
    DiagramMark mark() const { return m_mark; }
    /// Draws without selection and search marks (for export).
    static void setPlainDrawing(bool plain);

protected:
    const DiagramStyle &style() const { return *m_style; }
    /// Selection, search match and comparison mark around `outline` (item coordinates).
    void paintDecorations(QPainter *painter, const QPainterPath &outline) const;
    static constexpr qreal kDecorationMargin = 6;

private:
    QString m_key;
    const DiagramStyle *m_style;
    bool m_matched = false;
    DiagramMark m_mark = DiagramMark::None;
};

} // namespace rosarch
