#pragma once

#include <QSortFilterProxyModel>

namespace rosarch {

/// Filters the node tree by name or type; keeps the ancestors of a match (recursive
/// filtering) and all children of a matching row, so a matching node shows its ports.
class NodeFilterProxyModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit NodeFilterProxyModel(QObject *parent = nullptr);

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;
};

} // namespace rosarch
