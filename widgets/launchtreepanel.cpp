#include "widgets/launchtreepanel.h"
#include "jobs/stallprobe.h"
#include "widgets/launchtreemodel.h"
#include "widgets/nodefilterproxymodel.h"

#include <QAction>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QTreeView>
#include <QVBoxLayout>

namespace rosarch {

LaunchTreePanel::LaunchTreePanel(QWidget *parent)
    : FilteredTreePanel(parent), m_goToClass(new QAction(tr("&Go to Class"), this))
{
    m_proxy->setFilterColumns({LaunchTreeModel::NameColumn, LaunchTreeModel::NamespaceColumn,
                               LaunchTreeModel::ClassColumn, LaunchTreeModel::ExecutableColumn});
    m_filter->setPlaceholderText(tr("Filter by name, namespace, class or executable"));
    m_filter->setToolTip(tr("Shows the launch files, namespaces and node instances whose name, "
                            "namespace, class or executable contains this text. Esc clears "
                            "the filter."));
    m_tree->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_tree->setExpandsOnDoubleClick(false); // double-click goes to the class; arrows expand

    m_goToClass->setShortcut(QKeySequence(Qt::Key_F12));
    m_goToClass->setShortcutContext(Qt::WidgetShortcut);
    m_goToClass->setStatusTip(tr("Select the atomic node class this node instance runs"));
    connect(m_goToClass, &QAction::triggered, this, [this] {
        const QString classId = currentClassId();
        if (!classId.isEmpty())
            Q_EMIT classRequested(classId);
    });
    auto *separator = new QAction(this);
    separator->setSeparator(true);
    auto *expandAll = new QAction(tr("&Expand All"), this);
    connect(expandAll, &QAction::triggered, this, [this] { expandAllRows(); });
    auto *collapseAll = new QAction(tr("&Collapse All"), this);
    connect(collapseAll, &QAction::triggered, m_tree, &QTreeView::collapseAll);
    m_tree->addActions({m_goToClass, separator, expandAll, collapseAll});
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    const QList<QAction *> treeActions{m_goToClass, separator, expandAll, collapseAll};
    connect(m_tree, &QWidget::customContextMenuRequested, this,
            [this, treeActions](const QPoint &at) {
                QMenu menu(this);
                const QModelIndex index = m_proxy->mapToSource(m_tree->indexAt(at));
                Q_EMIT contextMenuRequested(&menu, index);
                if (!menu.isEmpty())
                    menu.addSeparator();
                menu.addActions(treeActions);
                menu.exec(m_tree->viewport()->mapToGlobal(at));
            });

    connect(m_tree, &QTreeView::doubleClicked, this, [this](const QModelIndex &index) {
        const QString classId = index.data(LaunchTreeModel::ClassIdRole).toString();
        if (!classId.isEmpty())
            Q_EMIT classRequested(classId);
        else
            m_tree->setExpanded(index.siblingAtColumn(0),
                                !m_tree->isExpanded(index.siblingAtColumn(0)));
    });
    connect(this, &FilteredTreePanel::currentSourceIndexChanged, this,
            &LaunchTreePanel::updateActions);

    setPlaceholderText(tr("No launch files analysed yet."));
    updateActions();
    updatePlaceholder();
}

void LaunchTreePanel::setModel(LaunchTreeModel *model)
{
    if (m_model)
        disconnect(m_model, nullptr, this, nullptr);
    m_model = model;
    m_proxy->setSourceModel(model);
    connect(model, &QAbstractItemModel::modelReset, this, &LaunchTreePanel::onModelReset);
    onModelReset();
}

bool LaunchTreePanel::isExpandable(const QModelIndex &proxyIndex) const
{
    return proxyIndex.data(LaunchTreeModel::KindRole).toInt() !=
           int(LaunchTreeModel::ItemKind::Parameters);
}

QString LaunchTreePanel::stableKeyOf(const QModelIndex &sourceIndex) const
{
    return m_model ? m_model->stableKey(sourceIndex) : QString();
}

QModelIndex LaunchTreePanel::sourceIndexOfKey(const QString &key) const
{
    return m_model ? m_model->indexOfStableKey(key) : QModelIndex();
}

void LaunchTreePanel::onModelReset()
{
    const StallScope scope("LaunchTreePanel::onModelReset");
    // Fit the columns to their content within bounds, so that a long plugin name does not
    // push the class (the link to the atomic nodes) out of sight.
    const QList<std::pair<int, int>> bounds{{LaunchTreeModel::NameColumn, 160},
                                            {LaunchTreeModel::NamespaceColumn, 90},
                                            {LaunchTreeModel::ClassColumn, 90},
                                            {LaunchTreeModel::ExecutableColumn, 120}};
    for (const auto &[column, minimum] : bounds) {
        m_tree->resizeColumnToContents(column);
        const int maximum = column == LaunchTreeModel::NameColumn ? 320 : 220;
        m_tree->setColumnWidth(column, qBound(minimum, m_tree->columnWidth(column) + 8, maximum));
    }
    updateActions();
    updatePlaceholder();
}

QString LaunchTreePanel::currentClassId() const
{
    return m_tree->currentIndex().data(LaunchTreeModel::ClassIdRole).toString();
}

void LaunchTreePanel::updateActions()
{
    m_goToClass->setEnabled(!currentClassId().isEmpty());
}

} // namespace rosarch
