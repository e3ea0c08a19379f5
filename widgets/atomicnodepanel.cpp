#include "atomicnodepanel.h"
#include "atomicnodemodel.h"
#include "nodefilterproxymodel.h"

#include <QAction>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLineEdit>
#include <QRegularExpression>
#include <QTreeView>
#include <QVBoxLayout>

namespace rosarch {

AtomicNodePanel::AtomicNodePanel(QWidget *parent)
    : QWidget(parent), m_proxy(new NodeFilterProxyModel(this)), m_filter(new QLineEdit(this)),
      m_tree(new QTreeView(this))
{
    m_filter->setPlaceholderText(tr("Filter by name or type (Ctrl+F)"));
    m_filter->setClearButtonEnabled(true);
    m_filter->setToolTip(tr("Shows the packages, nodes and ports whose name or type contains "
                            "this text. Esc clears the filter."));
    m_filter->installEventFilter(this);
    connect(m_filter, &QLineEdit::textChanged, this, &AtomicNodePanel::applyFilter);

    m_tree->setModel(m_proxy);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->setAllColumnsShowFocus(true);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                            QAbstractItemView::SelectedClicked);
    m_tree->header()->setStretchLastSection(true);
    m_tree->header()->setDefaultSectionSize(160);
    m_tree->setFrameShape(QFrame::NoFrame);
    // F2 on a node edits its description wherever the cursor column is; also on right-click.
    auto *editDescription = new QAction(tr("Edit &Description"), m_tree);
    editDescription->setShortcut(QKeySequence(Qt::Key_F2));
    editDescription->setShortcutContext(Qt::WidgetShortcut);
    editDescription->setStatusTip(tr("Describe the node's responsibility (undoable)"));
    connect(editDescription, &QAction::triggered, this, [this] {
        const QModelIndex description =
            m_tree->currentIndex().siblingAtColumn(AtomicNodeModel::DescriptionColumn);
        if (description.flags() & Qt::ItemIsEditable) {
            m_tree->setCurrentIndex(description);
            m_tree->edit(description);
        }
    });
    m_tree->addAction(editDescription);
    m_tree->setContextMenuPolicy(Qt::ActionsContextMenu);
    connect(m_tree->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) {
                Q_EMIT currentSourceIndexChanged(m_proxy->mapToSource(current));
            });

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_filter);
    layout->addWidget(m_tree);
    setFocusProxy(m_tree);
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
    m_tree->expandAll();
    m_tree->resizeColumnToContents(AtomicNodeModel::NameColumn);
    m_tree->resizeColumnToContents(AtomicNodeModel::TypeColumn);
    for (int c : {AtomicNodeModel::NameColumn, AtomicNodeModel::TypeColumn})
        m_tree->setColumnWidth(c, qBound(120, m_tree->columnWidth(c) + 8, 320));
    m_tree->setColumnWidth(AtomicNodeModel::DetailsColumn, 300);
}

void AtomicNodePanel::applyFilter(const QString &text)
{
    m_proxy->setFilterRegularExpression(QRegularExpression(
        QRegularExpression::escape(text.trimmed()), QRegularExpression::CaseInsensitiveOption));
    m_tree->expandAll();
}

QModelIndex AtomicNodePanel::currentSourceIndex() const
{
    return m_proxy->mapToSource(m_tree->currentIndex());
}

void AtomicNodePanel::selectSourceIndex(const QModelIndex &sourceIndex)
{
    QModelIndex proxyIndex = m_proxy->mapFromSource(sourceIndex.siblingAtColumn(0));
    if (!proxyIndex.isValid() && sourceIndex.isValid() && !m_filter->text().isEmpty()) {
        m_filter->clear();
        proxyIndex = m_proxy->mapFromSource(sourceIndex.siblingAtColumn(0));
    }
    if (!proxyIndex.isValid()) {
        m_tree->selectionModel()->clearCurrentIndex();
        m_tree->clearSelection();
        return;
    }
    for (QModelIndex p = proxyIndex.parent(); p.isValid(); p = p.parent())
        m_tree->expand(p);
    m_tree->selectionModel()->setCurrentIndex(proxyIndex, QItemSelectionModel::ClearAndSelect |
                                                              QItemSelectionModel::Rows);
    m_tree->scrollTo(proxyIndex);
}

void AtomicNodePanel::focusFilter()
{
    m_filter->setFocus(Qt::ShortcutFocusReason);
    m_filter->selectAll();
}

bool AtomicNodePanel::eventFilter(QObject *watched, QEvent *event)
{
    // Esc in a non-empty filter clears it rather than reaching a window-wide shortcut.
    if (watched == m_filter &&
        (event->type() == QEvent::ShortcutOverride || event->type() == QEvent::KeyPress)) {
        auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Escape && !m_filter->text().isEmpty()) {
            event->accept();
            if (event->type() == QEvent::KeyPress)
                m_filter->clear();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace rosarch
