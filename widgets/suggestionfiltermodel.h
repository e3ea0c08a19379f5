#pragma once

#include "core/suggestion.h"

#include <QSortFilterProxyModel>

#include <optional>

namespace rosarch {

/// Shows the suggestions of one status and/or one kind (all when unset).
class SuggestionFilterModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit SuggestionFilterModel(QObject *parent = nullptr);

    void setStatusFilter(std::optional<Suggestion::Status> status);
    void setKindFilter(std::optional<Suggestion::Kind> kind);
    std::optional<Suggestion::Status> statusFilter() const { return m_status; }
    std::optional<Suggestion::Kind> kindFilter() const { return m_kind; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    std::optional<Suggestion::Status> m_status;
    std::optional<Suggestion::Kind> m_kind;
};

} // namespace rosarch
