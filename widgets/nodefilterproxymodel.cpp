#include "widgets/nodefilterproxymodel.h"
#include "jobs/stallprobe.h"
#include "widgets/atomicnodemodel.h"

#include <QElapsedTimer>
#include <QTimer>

#include <algorithm>

namespace rosarch {

NodeFilterProxyModel::NodeFilterProxyModel(QObject *parent)
    : QSortFilterProxyModel(parent), m_columns{AtomicNodeModel::NameColumn,
                                               AtomicNodeModel::TypeColumn},
      m_slices(new QTimer(this))
{
    m_slices->setSingleShot(true);
    m_slices->setInterval(0);
    connect(m_slices, &QTimer::timeout, this, [this] { continueFiltering(kSliceMs); });
    // ancestors and descendants of a match are kept by filterAcceptsRow itself, once per row
    setRecursiveFilteringEnabled(false);
    setAutoAcceptChildRows(false);
    setFilterCaseSensitivity(Qt::CaseInsensitive);
}

void NodeFilterProxyModel::setSourceModel(QAbstractItemModel *model)
{
    for (const QMetaObject::Connection &c : std::as_const(m_sourceConnections))
        disconnect(c);
    m_sourceConnections.clear();
    forgetRows();
    if (model) {
        // Connected before the base class connects its own handlers: the rows are forgotten
        // before it filters the rows a change brought, and before rows move under a key.
        const auto forget = [this] { forgetRows(); };
        for (const auto signal :
             {&QAbstractItemModel::rowsAboutToBeInserted, &QAbstractItemModel::rowsInserted,
              &QAbstractItemModel::rowsAboutToBeRemoved, &QAbstractItemModel::rowsRemoved})
            m_sourceConnections << connect(model, signal, this, forget);
        m_sourceConnections << connect(model, &QAbstractItemModel::dataChanged, this, forget)
                            << connect(model, &QAbstractItemModel::rowsAboutToBeMoved, this, forget)
                            << connect(model, &QAbstractItemModel::rowsMoved, this, forget)
                            << connect(model, &QAbstractItemModel::layoutAboutToBeChanged, this,
                                       forget)
                            << connect(model, &QAbstractItemModel::layoutChanged, this, forget)
                            << connect(model, &QAbstractItemModel::modelAboutToBeReset, this,
                                       forget)
                            << connect(model, &QAbstractItemModel::modelReset, this, forget);
    }
    QSortFilterProxyModel::setSourceModel(model);
    if (model) {
        // The base class filters only the rows a change names; a row changed, added or
        // removed can keep or drop its ancestors too, as a whole filter does.
        const auto refilter = [this] {
            if (!filterRegularExpression().pattern().isEmpty())
                invalidateRowsFilter();
        };
        m_sourceConnections << connect(model, &QAbstractItemModel::dataChanged, this, refilter)
                            << connect(model, &QAbstractItemModel::rowsInserted, this, refilter)
                            << connect(model, &QAbstractItemModel::rowsRemoved, this, refilter);
    }
}

void NodeFilterProxyModel::forgetRows()
{
    m_slots.clear();
    m_rows.clear();
    // a walk in progress starts again over the changed rows
    m_pending.walk.clear();
    m_pending.walked = false;
    m_pending.matched = 0;
    m_pending.self.clear();
    if (m_pending.active)
        m_slices->start();
}

void NodeFilterProxyModel::setFilterTextInSlices(const QString &text)
{
    const QString trimmed = text.trimmed();
    m_pending.text = trimmed;
    m_pending.matched = 0;
    m_pending.self.clear();
    if (trimmed.isEmpty() || !sourceModel()) {
        m_pending.active = false;
        m_slices->stop();
        setFilterRegularExpression(QRegularExpression());
        Q_EMIT filterApplied();
        return;
    }
    m_pending.active = true;
    // the first slice at once: a small tree is filtered before the key shows
    continueFiltering(kSliceMs);
}

void NodeFilterProxyModel::continueFiltering(int budgetMs)
{
    if (!m_pending.active || !sourceModel())
        return;
    QElapsedTimer clock;
    clock.start();
    const QAbstractItemModel *model = sourceModel();
    // Every row gets a slot, its parent's slot and its texts, once per source model state.
    if (!m_pending.walked && m_pending.walk.empty())
        m_pending.walk.push_back({QModelIndex(), -1, 0});
    int steps = 0;
    while (!m_pending.walked) {
        if (++steps % 64 == 0 && clock.elapsed() >= budgetMs) {
            m_slices->start();
            return;
        }
        Frame &top = m_pending.walk.back();
        if (top.next >= model->rowCount(top.index)) {
            m_pending.walk.pop_back();
            m_pending.walked = m_pending.walk.empty();
            continue;
        }
        const QModelIndex child = model->index(top.next++, 0, top.index);
        const int parentSlot = top.slot;
        const int slot = slotOf(child);
        Row &row = m_rows[size_t(slot)];
        row.parent = parentSlot;
        if (row.texts.isEmpty())
            for (int column : std::as_const(m_columns))
                row.texts << child.siblingAtColumn(column).data(Qt::DisplayRole).toString();
        m_pending.walk.push_back({child, slot, 0});
    }
    // Then whether each row's own text matches.
    m_pending.self.resize(m_rows.size(), -1);
    while (m_pending.matched < m_rows.size()) {
        if (m_pending.matched % 256 == 255 && clock.elapsed() >= budgetMs) {
            m_slices->start();
            return;
        }
        const Row &row = m_rows[m_pending.matched];
        m_pending.self[m_pending.matched] =
            std::any_of(row.texts.cbegin(), row.texts.cend(), [this](const QString &t) {
                return t.contains(m_pending.text, Qt::CaseInsensitive);
            });
        ++m_pending.matched;
    }
    applyPending();
}

void NodeFilterProxyModel::applyPending()
{
    const StallScope scope("NodeFilterProxyModel applies a filter");
    const QRegularExpression re(QRegularExpression::escape(m_pending.text),
                                QRegularExpression::CaseInsensitiveOption);
    // The proxy's own way to a new filter walks every row it has mapped and moves rows one
    // range at a time, which on a large tree the person has browsed costs more than a key may.
    // Instead the filter is set while the rows keep their answers (nothing moves), the new
    // answers are found, and the mapping is dropped in one layout change: the views ask
    // again for the rows they show, and keep their current and expanded rows that stay.
    m_holdFilter = true;
    setFilterRegularExpression(re);
    m_holdFilter = false;
    m_matchedRe = re;
    ++m_generation;
    // Whether a row or an ancestor matches, and whether a descendant does, for every row: the
    // proxy then asks about each row in constant time.
    const size_t count = m_rows.size();
    for (size_t i = 0; i < count; ++i) {
        Row &row = m_rows[i];
        row.generation = m_generation;
        row.self = m_pending.self[i];
        row.above = -1;
        row.below = 0;
    }
    for (size_t i = 0; i < count; ++i) {
        // up to the first row whose answer is known, then down again
        QList<int> chain;
        int at = int(i);
        while (at >= 0 && m_rows[size_t(at)].above < 0) {
            chain << at;
            at = m_rows[size_t(at)].parent;
        }
        signed char above = at >= 0 ? m_rows[size_t(at)].above : 0;
        for (auto it = chain.crbegin(); it != chain.crend(); ++it) {
            Row &row = m_rows[size_t(*it)];
            above = row.self || above;
            row.above = above;
        }
        if (m_rows[i].self)
            for (int p = m_rows[i].parent; p >= 0 && !m_rows[size_t(p)].below;
                 p = m_rows[size_t(p)].parent)
                m_rows[size_t(p)].below = 1;
    }
    m_pending.active = false;
    m_pending.matched = 0;
    m_pending.self.clear();
    invalidate();
    Q_EMIT filterApplied();
}

void NodeFilterProxyModel::setFilterColumns(const QList<int> &columns)
{
    m_columns = columns;
    forgetRows();
    invalidateFilter();
}

bool NodeFilterProxyModel::followFilter() const
{
    const QRegularExpression re = filterRegularExpression();
    if (m_holdFilter)
        return !m_matchedRe.pattern().isEmpty();
    if (re != m_matchedRe) {
        m_matchedRe = re;
        ++m_generation;
    }
    return !re.pattern().isEmpty();
}

int NodeFilterProxyModel::slotOf(const QModelIndex &sourceIndex) const
{
    const auto key = std::make_pair(sourceIndex.internalId(), sourceIndex.row());
    auto it = m_slots.find(key);
    if (it == m_slots.end()) {
        it = m_slots.insert(key, int(m_rows.size()));
        m_rows.emplace_back();
    }
    Row &row = m_rows[size_t(*it)];
    if (row.generation != m_generation) {
        row.generation = m_generation;
        row.self = row.above = row.below = -1;
    }
    return *it;
}

bool NodeFilterProxyModel::selfMatches(const QModelIndex &sourceIndex) const
{
    Row &row = m_rows[size_t(slotOf(sourceIndex))];
    if (row.self >= 0)
        return row.self;
    if (row.texts.isEmpty()) {
        row.texts.reserve(m_columns.size());
        for (int column : m_columns)
            row.texts << sourceIndex.siblingAtColumn(column).data(Qt::DisplayRole).toString();
    }
    const QRegularExpression &re = m_matchedRe;
    row.self = std::any_of(row.texts.cbegin(), row.texts.cend(),
                           [&re](const QString &text) { return text.contains(re); });
    return row.self;
}

bool NodeFilterProxyModel::selfOrAncestorMatches(const QModelIndex &sourceIndex) const
{
    const int slot = slotOf(sourceIndex);
    if (m_rows[size_t(slot)].above >= 0)
        return m_rows[size_t(slot)].above;
    const QModelIndex parent = sourceIndex.parent();
    // the slot is looked up again: a row found on the way may have grown m_rows
    const bool above =
        selfMatches(sourceIndex) || (parent.isValid() && selfOrAncestorMatches(parent));
    m_rows[size_t(slot)].above = above;
    return above;
}

bool NodeFilterProxyModel::descendantMatches(const QModelIndex &sourceIndex) const
{
    const int slot = slotOf(sourceIndex);
    if (m_rows[size_t(slot)].below >= 0)
        return m_rows[size_t(slot)].below;
    bool below = false;
    const QAbstractItemModel *model = sourceModel();
    for (int r = 0, rows = model->rowCount(sourceIndex); r < rows && !below; ++r) {
        const QModelIndex child = model->index(r, 0, sourceIndex);
        below = selfMatches(child) || descendantMatches(child);
    }
    m_rows[size_t(slot)].below = below;
    return below;
}

bool NodeFilterProxyModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{

    if (!followFilter())
        return true;
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    return selfOrAncestorMatches(index) || descendantMatches(index);
}

bool NodeFilterProxyModel::matchesItself(const QModelIndex &proxyIndex) const
{
    const QModelIndex source = mapToSource(proxyIndex);
    return source.isValid() && followFilter() && selfMatches(source.siblingAtColumn(0));
}

} // namespace rosarch
