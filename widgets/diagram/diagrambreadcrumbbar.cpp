#include "diagrambreadcrumbbar.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace rosarch {

DiagramBreadcrumbBar::DiagramBreadcrumbBar(QWidget *parent)
    : QWidget(parent), m_layout(new QHBoxLayout(this))
{
    m_layout->setContentsMargins(4, 0, 4, 0);
    m_layout->setSpacing(0);
    m_layout->addStretch(1);
    // A deep path must not widen the diagram's dock (squeezing the panes beside it): what
    // does not fit is cut at the right, the note first; the tooltips and the picker remain.
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
}

QToolButton *DiagramBreadcrumbBar::button(const QString &id) const
{
    return findChild<QToolButton *>(QStringLiteral("crumb_") + id);
}

} // namespace rosarch
