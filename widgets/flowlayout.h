#pragma once

#include <QLayout>
#include <QList>

namespace rosarch {

/// Lays its widgets out left to right and starts a new row when the next one does not fit, so
/// that a bar of filters narrows to its widest widget instead of to the sum of them all (a
/// dock that cannot narrow makes the whole window wider than a laptop's screen). The widget
/// marked with setStretchWidget() takes what is left of its row.
class FlowLayout : public QLayout
{
public:
    explicit FlowLayout(QWidget *parent = nullptr);
    ~FlowLayout() override;

    /// The widget that grows to fill the rest of its row (e.g. a search field).
    void setStretchWidget(QWidget *widget) { m_stretch = widget; }

    void addItem(QLayoutItem *item) override;
    int count() const override { return int(m_items.size()); }
    QLayoutItem *itemAt(int index) const override { return m_items.value(index); }
    QLayoutItem *takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize minimumSize() const override;
    QSize sizeHint() const override;
    void setGeometry(const QRect &rect) override;

private:
    /// Places the items in `rect` (or only measures, when `apply` is false); the height used.
    int arrange(const QRect &rect, bool apply) const;

    QList<QLayoutItem *> m_items;
    QWidget *m_stretch = nullptr;
};

} // namespace rosarch
