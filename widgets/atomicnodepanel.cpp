#include "widgets/atomicnodepanel.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/nodefilterproxymodel.h"

#include <QAction>
#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QSet>
#include <QTreeView>

namespace rosarch {

AtomicNodePanel::AtomicNodePanel(QWidget *parent) : FilteredTreePanel(parent)
{
    m_filter->setPlaceholderText(tr("Filter by name or type (Ctrl+F)"));
    m_filter->setToolTip(tr("Shows the packages, nodes and ports whose name or type contains "
                            "this text. Esc clears the filter."));
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::SelectedClicked);
    m_tree->header()->setDefaultSectionSize(160);
    // F2 on a node edits its description wherever the cursor column is; also on right-click.
    auto *editDescription = new QAction(tr("Edit &Description"), m_tree);
    editDescription->setShortcut(QKeySequence(Qt::Key_F2));
    editDescription->setShortcutContext(Qt::WidgetShortcut);
    editDescription->setStatusTip(tr("Describe the node's responsibility (undoable)"));
    connect(editDescription, &QAction::triggered, this, [this] {
        // on a port, F2 renames it (a correction); on a class it edits the description
        if (m_model && m_model->kind(currentSourceIndex()) == AtomicNodeModel::ItemKind::Port) {
            Q_EMIT renameRequested(currentSourceIndex());
            return;
        }
        const QModelIndex description =
            m_tree->currentIndex().siblingAtColumn(AtomicNodeModel::DescriptionColumn);
        if (description.flags() & Qt::ItemIsEditable) {
            m_tree->setCurrentIndex(description);
            m_tree->edit(description);
        }
    });
    m_tree->addAction(editDescription);
    m_editDescription = editDescription;
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(m_tree, &QWidget::customContextMenuRequested, this, &AtomicNodePanel::showContextMenu);
    // Selecting a row shows its place already; activating a port or a parameter shows it again
    // (the source view may have moved on). A class's description edits on double-click.
    connect(m_tree, &QAbstractItemView::activated, this, [this](const QModelIndex &proxyIndex) {
        const QModelIndex index = m_proxy->mapToSource(proxyIndex);
        if (!m_model)
            return;
        const AtomicNodeModel::ItemKind kind = m_model->kind(index);
        if (kind != AtomicNodeModel::ItemKind::Port && kind != AtomicNodeModel::ItemKind::Parameter)
            return;
        if (const Evidence e = m_model->evidence(index); e.isValid())
            Q_EMIT evidenceRequested(e);
    });
    setPlaceholderText(tr("No node classes analysed yet."));
    updatePlaceholder();
}

bool AtomicNodePanel::isExpandable(const QModelIndex &proxyIndex) const
{
    if (proxyIndex.data(AtomicNodeModel::KindRole).toInt() !=
        int(AtomicNodeModel::ItemKind::Parameters))
        return true;
    if (m_filter->text().trimmed().isEmpty())
        return false;
    for (int row = 0, rows = m_proxy->rowCount(proxyIndex); row < rows; ++row)
        if (m_proxy->matchesItself(m_proxy->index(row, 0, proxyIndex)))
            return true;
    return false;
}

void AtomicNodePanel::expandRows()
{
    if (m_filter->text().trimmed().isEmpty()) {
        QSet<QModelIndex> keep;
        for (QModelIndex i = m_tree->currentIndex().siblingAtColumn(0); i.isValid(); i = i.parent())
            keep.insert(i);
        // only the open classes are visited: the cost follows what is shown
        for (int p = 0, packages = m_proxy->rowCount(); p < packages; ++p) {
            const QModelIndex package = m_proxy->index(p, 0);
            if (!m_tree->isExpanded(package))
                continue;
            for (int n = 0, nodes = m_proxy->rowCount(package); n < nodes; ++n) {
                const QModelIndex node = m_proxy->index(n, 0, package);
                const int rows = m_proxy->rowCount(node);
                const QModelIndex last =
                    rows > 0 ? m_proxy->index(rows - 1, 0, node) : QModelIndex();
                if (last.data(AtomicNodeModel::KindRole).toInt() ==
                        int(AtomicNodeModel::ItemKind::Parameters) &&
                    m_tree->isExpanded(last) && !keep.contains(last))
                    m_tree->collapse(last);
            }
        }
    }
    FilteredTreePanel::expandRows();
}

QString AtomicNodePanel::stableKeyOf(const QModelIndex &sourceIndex) const
{
    return m_model ? m_model->stableKey(sourceIndex) : QString();
}

QModelIndex AtomicNodePanel::sourceIndexOfKey(const QString &key) const
{
    return m_model ? m_model->indexOfStableKey(key) : QModelIndex();
}

// Besides editing, a port made through helpers offers each step from the node to the call
// that creates it, so the source view can walk the chain.
void AtomicNodePanel::showContextMenu(const QPoint &at)
{
    QMenu menu(this);
    const QModelIndex index = m_proxy->mapToSource(m_tree->indexAt(at));
    if (!m_model || m_model->kind(index) != AtomicNodeModel::ItemKind::Port)
        menu.addAction(m_editDescription);
    Q_EMIT contextMenuRequested(&menu, index);
    addChainActions(&menu, index);
    if (menu.isEmpty())
        return;
    menu.exec(m_tree->viewport()->mapToGlobal(at));
}

void AtomicNodePanel::addChainActions(QMenu *menu, const QModelIndex &sourceIndex)
{
    const Port *port = m_model ? m_model->port(sourceIndex) : nullptr;
    if (port && !port->viaEvidence.isEmpty()) {
        menu->addSection(tr("How the node reaches this port"));
        const auto place = [](const Evidence &e) {
            return QStringLiteral("%1:%2").arg(e.file).arg(e.line);
        };
        int step = 0;
        for (const Evidence &e : port->viaEvidence) {
            QAction *go = menu->addAction(tr("%1. Handed over at %2").arg(++step).arg(place(e)));
            connect(go, &QAction::triggered, this, [this, e] { Q_EMIT evidenceRequested(e); });
        }
        const Evidence created = port->evidence;
        QAction *go = menu->addAction(
            tr("%1. Created in %2 at %3").arg(++step).arg(port->via, place(created)));
        connect(go, &QAction::triggered, this,
                [this, created] { Q_EMIT evidenceRequested(created); });
    }
}

void AtomicNodePanel::setModel(AtomicNodeModel *model)
{
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    m_proxy->setSourceModel(model);
    connect(model, &QAbstractItemModel::modelReset, this, &AtomicNodePanel::onModelReset);
    onModelReset();
}

void AtomicNodePanel::onModelReset()
{
    m_tree->resizeColumnToContents(AtomicNodeModel::NameColumn);
    m_tree->resizeColumnToContents(AtomicNodeModel::TypeColumn);
    for (int c : {AtomicNodeModel::NameColumn, AtomicNodeModel::TypeColumn})
        m_tree->setColumnWidth(c, qBound(120, m_tree->columnWidth(c) + 8, 320));
    m_tree->setColumnWidth(AtomicNodeModel::DetailsColumn, 300);
    updatePlaceholder();
}

} // namespace rosarch
