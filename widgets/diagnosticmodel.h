#pragma once

#include "diagnostic.h"

#include <QAbstractTableModel>

namespace rosarch {

class Document;

/// The diagnostics of the last stage runs (stage 1's, then stage 2's) as a read-only table:
/// message, location, code.
class DiagnosticModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        MessageColumn,
        LocationColumn,
        CodeColumn,
        ColumnCount
    };

    explicit DiagnosticModel(Document *document, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    const Diagnostic *diagnostic(const QModelIndex &index) const;
    static QString severityLabel(Diagnostic::Severity severity);

private:
    Document *m_document;
};

} // namespace rosarch
