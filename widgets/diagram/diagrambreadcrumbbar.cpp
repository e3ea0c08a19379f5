#include "widgets/diagram/diagrambreadcrumbbar.h"

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
    QList<QLabel *> separators; // separators[i] comes before buttons[i + 1]
    QLabel *note = nullptr;
    int full = 0;
    for (QWidget *w : std::as_const(m_widgets)) {
        w->setVisible(true);
        if (auto *button = qobject_cast<QToolButton *>(w)) {
            const int i = int(buttons.size());
            buttons << button;
            button->setText(m_path.value(i).label);
            full += button->sizeHint().width();
        } else if (w->objectName() == QLatin1String("crumbNote")) {
            note = static_cast<QLabel *>(w);
            full += note->sizeHint().width();
        } else {
            auto *separator = static_cast<QLabel *>(w);
            separator->setText(QStringLiteral(" › "));
            separators << separator;
            full += separator->sizeHint().width();
        }
    }
    const QMargins margins = m_layout->contentsMargins();
    m_fullWidth = full + margins.left() + margins.right();
    updateGeometry();
    const auto shownWidth = [&] {
        int sum = 0;
        for (const QToolButton *button : std::as_const(buttons))
            sum += button->isVisibleTo(this) ? button->sizeHint().width() : 0;
        for (const QLabel *separator : std::as_const(separators))
            sum += separator->isVisibleTo(this) ? separator->sizeHint().width() : 0;
        return sum;
    };
    const int available = width() - margins.left() - margins.right();
    if (note)
        note->setVisible(shownWidth() + note->sizeHint().width() <= available);
    if (shownWidth() <= available || buttons.isEmpty())
        return;
    // The name shown must stay readable: the crumbs between the root and it go first, from the
    // root's side ("root › … › parent › shown"); their tooltips are the picker's and Back's.
    const int keepWhole =
        std::min(buttons.last()->sizeHint().width(), fontMetrics().averageCharWidth() * 16);
    for (qsizetype i = 1; i + 1 < buttons.size(); ++i) {
        const int others = shownWidth() - buttons.last()->sizeHint().width();
        if (others + keepWhole <= available)
            break;
        buttons[i]->setVisible(false);
        separators[i]->setVisible(false); // the one after it
        separators[0]->setText(QStringLiteral(" › … › "));
    }
    if (buttons.size() > 1 &&
        shownWidth() - buttons.last()->sizeHint().width() + keepWhole > available) {
        buttons.first()->setVisible(false); // even the root: "… › shown"
        separators[0]->setText(QStringLiteral("… › "));
    }
    if (shownWidth() <= available)
        return;
    // The name shown keeps what it needs to stay readable, the others share the rest; short
    // names give what they do not use to the rest.
    QList<QToolButton *> order;
    for (QToolButton *button : buttons.mid(0, buttons.size() - 1))
        if (button->isVisibleTo(this))
            order << button;
    std::sort(order.begin(), order.end(), [](const QToolButton *a, const QToolButton *b) {
        return a->sizeHint().width() < b->sizeHint().width();
    });
    order << buttons.last();
    int left = available;
    for (const QLabel *separator : std::as_const(separators))
        left -= separator->isVisibleTo(this) ? separator->sizeHint().width() : 0;
    const int reserve = std::min(keepWhole, left / 2);
    for (int i = 0; i < order.size(); ++i) {
        QToolButton *button = order[i];
        const bool shown = i + 1 == order.size();
        const int others = int(order.size()) - 1 - i; // this one and those after it
        const int share = std::max(0, shown ? left : (left - reserve) / others);
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
