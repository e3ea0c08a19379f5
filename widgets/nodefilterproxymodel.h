#pragma once

#include <QSortFilterProxyModel>

namespace rosarch {

/// Filters a tree by the text of some columns (the node tree: name and type); keeps the
/// ancestors of a match (recursive filtering) and all children of a matching row, so a
/// matching node shows its ports.
class NodeFilterProxyModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit NodeFilterProxyModel(QObject *parent = nullptr);

    /// The columns whose text is matched (default: the node tree's name and type).
    void setFilterColumns(const QList<int> &columns);
    /// Whether the row's own text matches the filter (not only a descendant's, or its
    /// parent's): the rows a filter is looking for.
    bool matchesItself(const QModelIndex &proxyIndex) const;

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    QList<int> m_columns;
};

} // namespace rosarch
