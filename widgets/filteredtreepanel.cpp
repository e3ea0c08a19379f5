#include "widgets/filteredtreepanel.h"
#include "jobs/stallprobe.h"
#include "widgets/nodefilterproxymodel.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QScopedValueRollback>
#include <QScrollBar>
#include <QTreeView>
#include <QVBoxLayout>

#include <functional>
#include <utility>

namespace rosarch {

namespace {

/// The panel's tree, able to put off laying out its rows: expanding a row of a tree view that
/// is laid out lays the rows out again at once, which over the hundreds of rows a filter opens
/// cost more than the filter; put off, the rows are laid out once, after.
class TreeView : public QTreeView
{
public:
    using QTreeView::QTreeView;
    void layOutLater() { scheduleDelayedItemsLayout(); }
};

} // namespace

FilteredTreePanel::FilteredTreePanel(QWidget *parent)
    : QWidget(parent), m_proxy(new NodeFilterProxyModel(this)), m_filter(new QLineEdit(this)),
      m_tree(new TreeView(this)), m_layout(new QVBoxLayout(this)), m_placeholder(new QLabel)
{
    m_filter->setClearButtonEnabled(true);
    m_filter->installEventFilter(this);
    // Each key shows at once: the rows are matched in slices between events, and the filter
    // applies when all are matched (at once on a small tree).
    connect(m_filter, &QLineEdit::textChanged, m_proxy,
            &NodeFilterProxyModel::setFilterTextInSlices);
    connect(m_proxy, &NodeFilterProxyModel::filterApplied, this, [this] {
        const StallScope scope("FilteredTreePanel expand rows");
        static_cast<TreeView *>(m_tree)->layOutLater();
        expandRows();
    });

    m_tree->setModel(m_proxy);
    m_tree->setUniformRowHeights(true);
    m_tree->setAlternatingRowColors(true);
    m_tree->setAllColumnsShowFocus(true);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->header()->setStretchLastSection(true);
    // Fitting a column to its content measures the rows around the visible area, not the
    // thousands a large workspace has: the fit runs on every re-run, on the UI thread.
    m_tree->header()->setResizeContentsPrecision(0);
    m_tree->setFrameShape(QFrame::NoFrame);
    connect(m_tree->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) {
                if (!m_restoring)
                    Q_EMIT currentSourceIndexChanged(m_proxy->mapToSource(current));
            });

    // A model that reshapes its rows for a small edit (a correction) and sets the property
    // "rosarch.keepsCurrent" during the reset keeps the person where they were: the current
    // row, found again by its stable key, and the scrolled place; the filter stays as typed.
    connect(m_proxy, &QAbstractItemModel::modelAboutToBeReset, this, [this] {
        rememberExpanded();
        keepCurrent();
    });
    connect(m_proxy, &QAbstractItemModel::modelReset, this, [this] {
        restoreExpanded();
        restoreCurrent();
    });

    m_layout->setContentsMargins(0, 0, 0, 0);
    m_layout->setSpacing(2);
    m_layout->addWidget(m_filter);
    m_layout->addWidget(m_tree, 1);
    // The placeholder lies over the empty tree's viewport: hiding the tree instead would hand
    // it the focus when shown again, which makes its first row current as if chosen.
    m_placeholder->setAlignment(Qt::AlignCenter);
    m_placeholder->setWordWrap(true);
    m_placeholder->setMargin(16);
    m_placeholder->setForegroundRole(QPalette::PlaceholderText);
    m_placeholder->setAttribute(Qt::WA_TransparentForMouseEvents);
    m_placeholder->setText(tr("Nothing analysed yet."));
    auto *overlay = new QVBoxLayout(m_tree->viewport());
    overlay->addWidget(m_placeholder);
    setFocusProxy(m_tree);
}

void FilteredTreePanel::expandRows()
{
    if (m_filter->text().trimmed().isEmpty())
        expandTop();
    else
        expandToMatches();
}

void FilteredTreePanel::expandToMatches()
{
    int shown = m_proxy->rowCount();
    QList<QModelIndex> matching; // kept rows that match themselves, in breadth-first order
    QList<QModelIndex> level;
    for (int row = 0; row < m_proxy->rowCount(); ++row)
        level << m_proxy->index(row, 0);
    // First the way to the matches: a row kept for a descendant opens.
    while (!level.isEmpty()) {
        QList<QModelIndex> next;
        for (const QModelIndex &index : std::as_const(level)) {
            if (!m_proxy->hasChildren(index) || !isExpandable(index))
                continue;
            if (m_proxy->matchesItself(index)) {
                matching << index;
                continue;
            }
            const int rows = m_proxy->rowCount(index);
            if (shown + rows > 4 * kExpandBudget)
                continue;
            m_tree->expand(index);
            shown += rows;
            for (int row = 0; row < rows; ++row)
                next << m_proxy->index(row, 0, index);
        }
        level = next;
    }
    // Then the matches themselves (a matching node shows its ports), while there is room.
    while (!matching.isEmpty() && shown < kExpandBudget) {
        QList<QModelIndex> next;
        for (const QModelIndex &index : std::as_const(matching)) {
            const int rows = m_proxy->rowCount(index);
            if (shown + rows > kExpandBudget)
                continue;
            m_tree->expand(index);
            shown += rows;
            for (int row = 0; row < rows; ++row)
                if (const QModelIndex child = m_proxy->index(row, 0, index);
                    m_proxy->hasChildren(child) && isExpandable(child))
                    next << child;
        }
        matching = next;
    }
}

bool FilteredTreePanel::isExpandable(const QModelIndex &) const
{
    return true;
}

QString FilteredTreePanel::stableKeyOf(const QModelIndex &) const
{
    return {};
}

QModelIndex FilteredTreePanel::sourceIndexOfKey(const QString &) const
{
    return {};
}

void FilteredTreePanel::keepCurrent()
{
    m_kept = {};
    const QAbstractItemModel *source = m_proxy->sourceModel();
    const QModelIndex current = currentSourceIndex();
    if (!source || !source->property("rosarch.keepsCurrent").toBool() || !current.isValid())
        return;
    m_kept.valid = true;
    m_kept.key = stableKeyOf(current);
    if (m_kept.key.isEmpty())
        for (QModelIndex i = current.siblingAtColumn(0); i.isValid(); i = i.parent())
            m_kept.names.prepend(i.data().toString());
    m_kept.scroll = m_tree->verticalScrollBar()->value();
}

void FilteredTreePanel::restoreCurrent()
{
    if (!m_kept.valid)
        return;
    const Kept kept = std::exchange(m_kept, {});
    const QModelIndex source =
        kept.key.isEmpty() ? sourceIndexOfNames(kept.names) : sourceIndexOfKey(kept.key);
    // Not selectSourceIndex(): the filter a person typed stays, even if the row no longer
    // passes it.
    const QModelIndex proxyIndex = m_proxy->mapFromSource(source.siblingAtColumn(0));
    if (!proxyIndex.isValid()) { // gone (an addition undone) or filtered out
        Q_EMIT currentSourceIndexChanged({});
        return;
    }
    for (QModelIndex p = proxyIndex.parent(); p.isValid(); p = p.parent())
        m_tree->expand(p);
    {
        // the same element as before the reset: nothing to tell the other views
        const QScopedValueRollback restoring(m_restoring, true);
        m_tree->selectionModel()->setCurrentIndex(proxyIndex, QItemSelectionModel::ClearAndSelect |
                                                                  QItemSelectionModel::Rows);
    }
    m_tree->doItemsLayout(); // the scroll range of the rows shown again
    m_tree->verticalScrollBar()->setValue(kept.scroll);
}

QModelIndex FilteredTreePanel::sourceIndexOfNames(const QStringList &names) const
{
    const QAbstractItemModel *source = m_proxy->sourceModel();
    QModelIndex at;
    for (const QString &name : names) {
        QModelIndex next;
        for (int row = 0, rows = source ? source->rowCount(at) : 0; row < rows; ++row)
            if (const QModelIndex i = source->index(row, 0, at); i.data().toString() == name) {
                next = i;
                break;
            }
        if (!next.isValid())
            return {};
        at = next;
    }
    return at;
}

void FilteredTreePanel::expandAllRows()
{
    std::function<void(const QModelIndex &)> expand = [&](const QModelIndex &parent) {
        for (int row = 0, rows = m_proxy->rowCount(parent); row < rows; ++row) {
            const QModelIndex index = m_proxy->index(row, 0, parent);
            if (!m_proxy->hasChildren(index) || !isExpandable(index))
                continue;
            m_tree->expand(index);
            expand(index);
        }
    };
    expand({});
}

void FilteredTreePanel::expandTop()
{
    QList<QModelIndex> level;
    int shown = m_proxy->rowCount();
    for (int row = 0; row < m_proxy->rowCount(); ++row)
        level << m_proxy->index(row, 0);
    while (!level.isEmpty() && shown < kExpandBudget) {
        QList<QModelIndex> next;
        for (const QModelIndex &index : std::as_const(level)) {
            if (!m_proxy->hasChildren(index) || !isExpandable(index))
                continue;
            const int rows = m_proxy->rowCount(index);
            if (shown + rows > kExpandBudget)
                return;
            m_tree->expand(index);
            shown += rows;
            for (int row = 0; row < rows; ++row)
                next << m_proxy->index(row, 0, index);
        }
        level = next;
    }
}

QString FilteredTreePanel::rowKey(const QModelIndex &proxyIndex) const
{
    QStringList names;
    for (QModelIndex i = proxyIndex; i.isValid(); i = i.parent())
        names.prepend(i.data().toString());
    return names.join(QChar(0x1f));
}

void FilteredTreePanel::rememberExpanded()
{
    m_expanded.clear();
    // only the open rows are visited: the cost follows what is shown
    std::function<void(const QModelIndex &)> visit = [&](const QModelIndex &parent) {
        for (int row = 0, rows = m_proxy->rowCount(parent); row < rows; ++row) {
            const QModelIndex index = m_proxy->index(row, 0, parent);
            if (!m_tree->isExpanded(index))
                continue;
            m_expanded.insert(rowKey(index));
            visit(index);
        }
    };
    visit({});
}

void FilteredTreePanel::restoreExpanded()
{
    if (m_expanded.isEmpty()) {
        expandRows();
        return;
    }
    const QSet<QString> expanded = std::exchange(m_expanded, {});
    std::function<void(const QModelIndex &)> visit = [&](const QModelIndex &parent) {
        for (int row = 0, rows = m_proxy->rowCount(parent); row < rows; ++row) {
            const QModelIndex index = m_proxy->index(row, 0, parent);
            if (!expanded.contains(rowKey(index)))
                continue;
            m_tree->expand(index);
            visit(index);
        }
    };
    visit({});
}

void FilteredTreePanel::setPlaceholderText(const QString &text)
{
    m_placeholder->setText(text);
}

void FilteredTreePanel::updatePlaceholder()
{
    // The filter stays enabled, and the tree shown: either change would move the focus.
    const bool empty = !m_proxy->sourceModel() || m_proxy->sourceModel()->rowCount() == 0;
    m_placeholder->setVisible(empty);
}

QModelIndex FilteredTreePanel::currentSourceIndex() const
{
    return m_proxy->mapToSource(m_tree->currentIndex());
}

void FilteredTreePanel::selectSourceIndex(const QModelIndex &sourceIndex)
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

QString FilteredTreePanel::currentStableKey() const
{
    const QModelIndex current = currentSourceIndex();
    return current.isValid() ? stableKeyOf(current) : QString();
}

bool FilteredTreePanel::selectStableKey(const QString &key)
{
    const QModelIndex index = key.isEmpty() ? QModelIndex() : sourceIndexOfKey(key);
    if (!index.isValid())
        return false;
    selectSourceIndex(index);
    return true;
}

void FilteredTreePanel::focusFilter()
{
    m_filter->setFocus(Qt::ShortcutFocusReason);
    m_filter->selectAll();
}

bool FilteredTreePanel::eventFilter(QObject *watched, QEvent *event)
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
