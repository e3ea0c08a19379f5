#include "widgets/architecturediffview.h"

#include <QHeaderView>
#include <QLabel>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace rosarch {

namespace {

/// Green, red and amber that read on the light and the dark palette: darker on a light
/// base, lighter on a dark one.
QColor changeColour(ArchitectureChange::Kind kind, const QPalette &palette)
{
    const bool dark = palette.color(QPalette::Base).lightness() < 128;
    switch (kind) {
    case ArchitectureChange::Kind::Added:
        return dark ? QColor(0x81, 0xc7, 0x84) : QColor(0x1b, 0x5e, 0x20);
    case ArchitectureChange::Kind::Removed:
        return dark ? QColor(0xef, 0x9a, 0x9a) : QColor(0xb7, 0x1c, 0x1c);
    case ArchitectureChange::Kind::Changed:
    case ArchitectureChange::Kind::Renamed:
        break;
    }
    return dark ? QColor(0xff, 0xcc, 0x80) : QColor(0x9a, 0x55, 0x00);
}

QString mark(ArchitectureChange::Kind kind)
{
    switch (kind) {
    case ArchitectureChange::Kind::Added:
        return QStringLiteral("+");
    case ArchitectureChange::Kind::Removed:
        return QStringLiteral("−");
    case ArchitectureChange::Kind::Changed:
    case ArchitectureChange::Kind::Renamed:
        break;
    }
    return QStringLiteral("~");
}

} // namespace

ArchitectureDiffView::ArchitectureDiffView(QWidget *parent)
    : QWidget(parent), m_summary(new QLabel(this)), m_tree(new QTreeWidget(this))
{
    m_summary->setWordWrap(true);
    m_summary->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_tree->setColumnCount(3);
    m_tree->setHeaderLabels({tr("Change"), tr("Element"), tr("What")});
    m_tree->header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::ResizeToContents);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(m_summary);
    layout->addWidget(m_tree, 1);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem *item) {
        bool ok = false;
        const int i = item ? item->data(0, Qt::UserRole).toInt(&ok) : -1;
        if (ok && i >= 0 && i < m_changes.size())
            Q_EMIT changeSelected(m_changes.at(i));
    });
    setMessage(tr("Compare the recovered architecture with an earlier recovery (an artifact "
                  "folder or a workspace) or a git revision: File › Compare Architecture."));
}

void ArchitectureDiffView::setMessage(const QString &message)
{
    m_tree->clear();
    m_changes.clear();
    m_summary->setText(message);
}

QString ArchitectureDiffView::summary() const
{
    return m_summary->text();
}

void ArchitectureDiffView::setChanges(const QList<ArchitectureChange> &changes,
                                      const QString &before, const QString &after)
{
    m_tree->clear();
    m_changes = changes;
    int counts[4] = {0, 0, 0, 0};
    QHash<QString, QTreeWidgetItem *> groups;
    for (int i = 0; i < changes.size(); ++i) {
        const ArchitectureChange &c = changes.at(i);
        ++counts[int(c.kind)];
        QTreeWidgetItem *group = groups.value(c.scope);
        if (!group) {
            group = new QTreeWidgetItem(m_tree, {QString(), c.scope});
            QFont bold = group->font(1);
            bold.setBold(true);
            group->setFont(1, bold);
            group->setFirstColumnSpanned(true);
            group->setText(0, c.scope);
            group->setFont(0, bold);
            groups.insert(c.scope, group);
        }
        const QString what = c.kind == ArchitectureChange::Kind::Added ? c.after
                             : c.kind == ArchitectureChange::Kind::Removed
                                 ? c.before
                                 : c.before + QStringLiteral(" → ") + c.after;
        auto *item = new QTreeWidgetItem(
            group, {mark(c.kind) + QLatin1Char(' ') + ArchitectureChange::kindName(c.kind),
                    c.element, what});
        item->setData(0, Qt::UserRole, i);
        const QColor colour = changeColour(c.kind, palette());
        for (int col = 0; col < 3; ++col)
            item->setForeground(col, colour);
        item->setToolTip(2, c.kind == ArchitectureChange::Kind::Added ? tr("Added: %1").arg(c.after)
                            : c.kind == ArchitectureChange::Kind::Removed
                                ? tr("Removed: %1").arg(c.before)
                                : tr("Before: %1\nAfter: %2").arg(c.before, c.after));
        item->setToolTip(1, tr("Select the row to show the %1 in the other views").arg(c.element));
    }
    m_tree->expandAll();
    m_summary->setText(
        changes.isEmpty()
            ? tr("No architecture changes from %1 to %2.").arg(before, after)
            : tr("%1 changes from %2 to %3: %4 added, %5 removed, %6 changed, %7 renamed.")
                  .arg(changes.size())
                  .arg(before, after)
                  .arg(counts[0])
                  .arg(counts[1])
                  .arg(counts[2])
                  .arg(counts[3]));
}

} // namespace rosarch
