#pragma once

#include "project/correctedmodel.h"

#include <QAbstractTableModel>
#include <QHash>

namespace rosarch {

class Document;

/// The corrections of the project as a table, in the order they were made: kind, target,
/// old → new, reason, author, time, and whether it still applies. One that matches nothing in
/// the current model (orphaned) says why, in a quiet warning style. Read-only: reverting and
/// re-targeting go through the Document.
class CorrectionModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        KindColumn,
        TargetColumn,
        ChangeColumn,
        ReasonColumn,
        AuthorColumn,
        TimeColumn,
        StatusColumn,
        ColumnCount
    };
    enum Role
    {
        IdRole = Qt::UserRole + 1, ///< "c3"
        TargetRole,                ///< the stable key
        OrphanedRole,              ///< bool
    };

    explicit CorrectionModel(Document *document, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    /// The row of correction `id` (-1 when none).
    int rowOf(const QString &id) const;
    /// Why correction `id` matches nothing ("" when it applies).
    QString orphanReason(const QString &id) const;
    /// "Rename", "Set name", ... as shown.
    static QString kindText(int kind);

private:
    void refresh();

    Document *m_document;
    QList<Correction> m_corrections;
    QHash<QString, QString> m_orphans; ///< correction id → why it matches nothing
};

} // namespace rosarch
