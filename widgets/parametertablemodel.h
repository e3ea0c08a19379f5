#pragma once

#include "core/parameterview.h"

#include <QAbstractTableModel>
#include <QList>

namespace rosarch {

/// One node instance's parameters (declaration joined with the value in effect), or one node
/// class's declared parameters, as a table: name, type, default, value, source, description.
/// Read-only; the Parameters panel sorts and filters it.
class ParameterTableModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        NameColumn,
        TypeColumn,
        DefaultColumn,
        ValueColumn,
        SourceColumn,
        DescriptionColumn,
        ColumnCount
    };
    enum Role
    {
        EvidenceFileRole = Qt::UserRole + 1, ///< where the value is set, else the declaration
        EvidenceLineRole,
    };

    explicit ParameterTableModel(QObject *parent = nullptr);

    void setParameters(const QList<InstanceParameter> &parameters);
    const QList<InstanceParameter> &parameters() const { return m_parameters; }
    /// The parameters of `index`'s row (null for an invalid index).
    const InstanceParameter *parameter(const QModelIndex &index) const;

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    /// A class's declarations as rows without values (the node list's view of a class).
    static QList<InstanceParameter> declaredOnly(const QList<ParameterDeclaration> &declared);

private:
    QString sourceText(const InstanceParameter &p) const;

    QList<InstanceParameter> m_parameters;
};

} // namespace rosarch
