#include "widgets/correctionpanel.h"
#include "widgets/correctionmodel.h"

#include <QAction>
#include <QHeaderView>
#include <QLabel>
#include <QScopedValueRollback>
#include <QTableView>
#include <QToolBar>
#include <QVBoxLayout>

namespace rosarch {

CorrectionPanel::CorrectionPanel(QWidget *parent)
    : QWidget(parent), m_table(new QTableView(this)), m_placeholder(new QLabel(this)),
      m_remove(new QAction(tr("&Remove Correction"), this)),
      m_retarget(new QAction(tr("Re-&target\u2026"), this))
{
    m_remove->setShortcut(QKeySequence::Delete);
    m_remove->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_remove->setStatusTip(tr("Revert what the selected corrections changed (undoable)"));
    m_retarget->setStatusTip(
        tr("Point an orphaned correction at another element of the same kind (undoable)"));
    connect(m_remove, &QAction::triggered, this, [this] {
        const QStringList ids = selectedIds();
        if (!ids.isEmpty())
            Q_EMIT removeRequested(ids);
    });
    connect(m_retarget, &QAction::triggered, this, [this] {
        if (!currentId().isEmpty())
            Q_EMIT retargetRequested(currentId());
    });

    auto *toolBar = new QToolBar(this);
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    toolBar->setIconSize(QSize(16, 16));
    toolBar->addAction(m_remove);
    toolBar->addAction(m_retarget);

    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->setWordWrap(false);
    m_table->setAlternatingRowColors(true);
    m_table->setShowGrid(false);
    m_table->setFrameShape(QFrame::NoFrame);
    m_table->addActions({m_remove, m_retarget});
    m_table->setContextMenuPolicy(Qt::ActionsContextMenu);

    m_placeholder->setAlignment(Qt::AlignCenter);
    m_placeholder->setWordWrap(true);
    m_placeholder->setMargin(16);
    m_placeholder->setForegroundRole(QPalette::PlaceholderText);
    m_placeholder->setText(tr("No corrections yet. Right-click an element in the node list, the "
                              "launch tree or the diagram to rename, retype, remove, add or "
                              "review it."));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(toolBar);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_placeholder, 1);
    updateActions();
}

void CorrectionPanel::setModel(CorrectionModel *model)
{
    m_model = model;
    m_table->setModel(model);
    m_table->horizontalHeader()->resizeSection(CorrectionModel::KindColumn, 130);
    m_table->horizontalHeader()->resizeSection(CorrectionModel::TargetColumn, 300);
    m_table->horizontalHeader()->resizeSection(CorrectionModel::ChangeColumn, 220);
    m_table->horizontalHeader()->resizeSection(CorrectionModel::ReasonColumn, 200);
    connect(m_table->selectionModel(), &QItemSelectionModel::currentRowChanged, this,
            [this](const QModelIndex &current) {
                updateActions();
                if (current.isValid() && !m_listing)
                    Q_EMIT correctionActivated(current.data(CorrectionModel::IdRole).toString());
            });
    connect(m_table->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &CorrectionPanel::updateActions);
    connect(model, &QAbstractItemModel::modelReset, this, [this] {
        updateActions();
        updatePlaceholder();
    });
    updatePlaceholder();
}

QStringList CorrectionPanel::selectedIds() const
{
    QStringList ids;
    if (!m_model)
        return ids;
    QModelIndexList rows = m_table->selectionModel()->selectedRows();
    std::sort(rows.begin(), rows.end(),
              [](const QModelIndex &a, const QModelIndex &b) { return a.row() < b.row(); });
    for (const QModelIndex &i : rows)
        ids.append(i.data(CorrectionModel::IdRole).toString());
    if (ids.isEmpty() && !currentId().isEmpty())
        ids.append(currentId());
    return ids;
}

QString CorrectionPanel::currentId() const
{
    return m_table->currentIndex().data(CorrectionModel::IdRole).toString();
}

bool CorrectionPanel::selectCorrection(const QString &id)
{
    const int row = m_model ? m_model->rowOf(id) : -1;
    if (row < 0)
        return false;
    m_table->selectionModel()->setCurrentIndex(
        m_model->index(row, 0), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    return true;
}

bool CorrectionPanel::listCorrection(const QString &id)
{
    const QScopedValueRollback listing(m_listing, true);
    if (!selectCorrection(id))
        return false;
    m_table->scrollTo(m_table->currentIndex());
    return true;
}

void CorrectionPanel::updateActions()
{
    const QModelIndex current = m_table->currentIndex();
    m_remove->setEnabled(current.isValid() ||
                         (m_table->selectionModel() && m_table->selectionModel()->hasSelection()));
    m_retarget->setEnabled(current.isValid() &&
                           current.data(CorrectionModel::OrphanedRole).toBool());
}

void CorrectionPanel::updatePlaceholder()
{
    const bool empty = !m_model || m_model->rowCount() == 0;
    m_table->setVisible(!empty);
    m_placeholder->setVisible(empty);
}

} // namespace rosarch
