#include "nodefilterproxymodel.h"
#include "atomicnodemodel.h"

namespace rosarch {

NodeFilterProxyModel::NodeFilterProxyModel(QObject *parent)
    : QSortFilterProxyModel(parent), m_columns{AtomicNodeModel::NameColumn,
                                               AtomicNodeModel::TypeColumn}
{
    setRecursiveFilteringEnabled(true);
    setAutoAcceptChildRows(true);
    setFilterCaseSensitivity(Qt::CaseInsensitive);
}

void NodeFilterProxyModel::setFilterColumns(const QList<int> &columns)
{
    m_columns = columns;
    invalidateFilter();
}

bool NodeFilterProxyModel::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const
{
    const QRegularExpression re = filterRegularExpression();
    if (re.pattern().isEmpty())
        return true;
    for (int column : m_columns) {
        const QModelIndex index = sourceModel()->index(sourceRow, column, sourceParent);
        if (index.data(Qt::DisplayRole).toString().contains(re))
            return true;
    }
    return false;
}

bool NodeFilterProxyModel::matchesItself(const QModelIndex &proxyIndex) const
{
    const QModelIndex source = mapToSource(proxyIndex);
    return source.isValid() && filterAcceptsRow(source.row(), source.parent());
}

} // namespace rosarch
