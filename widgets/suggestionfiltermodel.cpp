#include "widgets/suggestionfiltermodel.h"
#include "widgets/suggestionmodel.h"

namespace rosarch {

SuggestionFilterModel::SuggestionFilterModel(QObject *parent) : QSortFilterProxyModel(parent)
{
    // A decision changes the status role; the row must leave a "Pending" view at once.
    setDynamicSortFilter(true);
}

void SuggestionFilterModel::setStatusFilter(std::optional<Suggestion::Status> status)
{
    if (status == m_status)
        return;
    m_status = status;
    invalidateFilter();
}

void SuggestionFilterModel::setKindFilter(std::optional<Suggestion::Kind> kind)
{
    if (kind == m_kind)
        return;
    m_kind = kind;
    invalidateFilter();
}

bool SuggestionFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
    if (m_status && index.data(SuggestionModel::StatusRole).toInt() != int(*m_status))
        return false;
    if (m_kind && index.data(SuggestionModel::KindRole).toInt() != int(*m_kind))
        return false;
    return true;
}

} // namespace rosarch
