#include "widgets/flowlayout.h"

#include <QWidget>

#include <algorithm>

namespace rosarch {

FlowLayout::FlowLayout(QWidget *parent) : QLayout(parent) {}

FlowLayout::~FlowLayout()
{
    qDeleteAll(m_items);
}

void FlowLayout::addItem(QLayoutItem *item)
{
    m_items.append(item);
}

QLayoutItem *FlowLayout::takeAt(int index)
{
    return index >= 0 && index < m_items.size() ? m_items.takeAt(index) : nullptr;
}

int FlowLayout::heightForWidth(int width) const
{
    return arrange(QRect(0, 0, width, 0), false);
}

QSize FlowLayout::minimumSize() const
{
    QSize size;
    for (const QLayoutItem *item : m_items)
        if (!item->isEmpty())
            size = size.expandedTo(item->minimumSize());
    const QMargins m = contentsMargins();
    return size + QSize(m.left() + m.right(), m.top() + m.bottom());
}

QSize FlowLayout::sizeHint() const
{
    // All on one row when there is room for it.
    int width = 0;
    int height = 0;
    for (const QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        width += item->sizeHint().width() + (width > 0 ? spacing() : 0);
        height = std::max(height, item->sizeHint().height());
    }
    const QMargins m = contentsMargins();
    return {width + m.left() + m.right(), height + m.top() + m.bottom()};
}

void FlowLayout::setGeometry(const QRect &rect)
{
    QLayout::setGeometry(rect);
    arrange(rect, true);
}

int FlowLayout::arrange(const QRect &rect, bool apply) const
{
    const QRect area = rect.marginsRemoved(contentsMargins());
    const int gap = std::max(0, spacing());
    // Split into rows first, so that a row's stretch widget and heights are known.
    QList<QList<QLayoutItem *>> rows(1);
    int x = 0;
    for (QLayoutItem *item : m_items) {
        if (item->isEmpty())
            continue;
        const int w = std::min(item->sizeHint().width(), area.width());
        if (!rows.last().isEmpty() && x + gap + w > area.width()) {
            rows.append(QList<QLayoutItem *>());
            x = 0;
        }
        x += (rows.last().isEmpty() ? 0 : gap) + w;
        rows.last().append(item);
    }
    if (rows.last().isEmpty()) // nothing to show
        return contentsMargins().top() + contentsMargins().bottom();
    int y = area.top();
    for (const QList<QLayoutItem *> &row : std::as_const(rows)) {
        int used = 0;
        int height = 0;
        for (QLayoutItem *item : row) {
            used += std::min(item->sizeHint().width(), area.width());
            height = std::max(height, item->sizeHint().height());
        }
        used += gap * int(row.size() - 1);
        const int spare = std::max(0, area.width() - used);
        int left = area.left();
        for (QLayoutItem *item : row) {
            int w = std::min(item->sizeHint().width(), area.width());
            if (item->widget() && item->widget() == m_stretch)
                w += spare;
            if (apply)
                item->setGeometry(QRect(left, y + (height - item->sizeHint().height()) / 2, w,
                                        item->sizeHint().height()));
            left += w + gap;
        }
        y += height + gap;
    }
    return y - gap - area.top() + contentsMargins().top() + contentsMargins().bottom();
}

} // namespace rosarch
