#include "diagrambreadcrumbbar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QResizeEvent>
#include <QToolButton>

#include <algorithm>

namespace rosarch {

DiagramBreadcrumbBar::DiagramBreadcrumbBar(QWidget *parent)
    : QWidget(parent), m_layout(new QHBoxLayout(this))
{
    m_layout->setContentsMargins(4, 0, 4, 0);
    m_layout->setSpacing(0);
    m_layout->addStretch(1);
    // A deep path must not widen the diagram's dock (squeezing the panes beside it): what
    // does not fit goes, the note first, then the middle of each name (fitToWidth); the
    // tooltips and the picker remain.
    setMinimumWidth(fontMetrics().averageCharWidth() * 12);
}

void DiagramBreadcrumbBar::setPath(const QList<Crumb> &path, const QString &note,
                                   const QString &noteToolTip)
{
    qDeleteAll(m_widgets);
    m_widgets.clear();
    m_path = path;
    for (int i = 0; i < path.size(); ++i) {
        const Crumb &crumb = path[i];
        if (i > 0) {
            auto *separator = new QLabel(QStringLiteral(" › "), this);
            separator->setForegroundRole(QPalette::PlaceholderText);
            m_layout->insertWidget(m_layout->count() - 1, separator);
            m_widgets << separator;
        }
        auto *button = new QToolButton(this);
        button->setObjectName(QStringLiteral("crumb_") + crumb.id);
        button->setText(crumb.label);
        button->setToolTip(crumb.toolTip);
        button->setAutoRaise(true);
        const bool last = i == path.size() - 1;
        if (last) {
            QFont f = button->font();
            f.setBold(true);
            button->setFont(f);
        }
        connect(button, &QToolButton::clicked, this, [this, id = crumb.id, last] {
            if (!last)
                Q_EMIT crumbClicked(id);
        });
        m_layout->insertWidget(m_layout->count() - 1, button);
        m_widgets << button;
    }
    if (!note.isEmpty()) {
        auto *label = new QLabel(note, this);
        label->setObjectName(QStringLiteral("crumbNote"));
        label->setForegroundRole(QPalette::PlaceholderText);
        label->setToolTip(noteToolTip);
        m_layout->insertWidget(m_layout->count() - 1, label);
        m_widgets << label;
    }
    fitToWidth();
}

QSize DiagramBreadcrumbBar::sizeHint() const
{
    return {m_fullWidth, QWidget::sizeHint().height()};
}

void DiagramBreadcrumbBar::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    if (event->size().width() != event->oldSize().width())
        fitToWidth();
}

void DiagramBreadcrumbBar::fitToWidth()
{
    QList<QToolButton *> buttons;
    QLabel *note = nullptr;
    int fixed = 0; // separators
    int full = 0;
    for (QWidget *w : std::as_const(m_widgets)) {
        if (auto *button = qobject_cast<QToolButton *>(w)) {
            const int i = int(buttons.size());
            buttons << button;
            button->setText(m_path.value(i).label);
            full += button->sizeHint().width();
        } else if (w->objectName() == QLatin1String("crumbNote")) {
            note = static_cast<QLabel *>(w);
            full += note->sizeHint().width();
        } else {
            fixed += w->sizeHint().width();
        }
    }
    const QMargins margins = m_layout->contentsMargins();
    m_fullWidth = full + fixed + margins.left() + margins.right();
    updateGeometry();
    const int available = width() - margins.left() - margins.right() - fixed;
    int crumbs = 0;
    for (const QToolButton *button : std::as_const(buttons))
        crumbs += button->sizeHint().width();
    if (note)
        note->setVisible(crumbs + note->sizeHint().width() <= available);
    if (crumbs <= available || buttons.isEmpty())
        return;
    // The name shown gets two shares, the others one each; short names give what they do
    // not use to the rest.
    QList<QToolButton *> order = buttons.mid(0, buttons.size() - 1);
    std::sort(order.begin(), order.end(), [](const QToolButton *a, const QToolButton *b) {
        return a->sizeHint().width() < b->sizeHint().width();
    });
    order << buttons.last();
    int left = available;
    for (int i = 0; i < order.size(); ++i) {
        QToolButton *button = order[i];
        const int shares = int(order.size() - i) + 1;
        const int share = std::max(0, i + 1 == order.size() ? left : left / shares);
        const int wanted = button->sizeHint().width();
        if (wanted > share) {
            const QFontMetrics fm(button->font());
            const int padding = wanted - fm.horizontalAdvance(button->text());
            button->setText(fm.elidedText(button->text(), Qt::ElideMiddle,
                                          std::max(fm.averageCharWidth() * 3, share - padding)));
        }
        left -= button->sizeHint().width();
    }
}

QToolButton *DiagramBreadcrumbBar::button(const QString &id) const
{
    return findChild<QToolButton *>(QStringLiteral("crumb_") + id);
}

} // namespace rosarch
