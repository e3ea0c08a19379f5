#pragma once

#include "core/suggestion.h"
#include "suggestions/suggestionitem.h"

#include <QAbstractTableModel>
#include <QHash>

namespace rosarch {

class Document;

/// The suggestions of the Document as a read-only table: kind (with a status mark), target,
/// proposal, origin and evidence. Decided rows are greyed; rejected proposals struck out.
class SuggestionModel : public QAbstractTableModel
{
    Q_OBJECT
public:
    enum Column
    {
        KindColumn,
        TargetColumn,
        ProposalColumn,
        OriginColumn,
        EvidenceColumn,
        ColumnCount
    };
    enum Role
    {
        IdRole = Qt::UserRole + 1, ///< the suggestion id
        StatusRole,                ///< int(Suggestion::Status)
        KindRole,                  ///< int(Suggestion::Kind)
    };

    explicit SuggestionModel(Document *document, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    Document *document() const { return m_document; }
    const Suggestion *suggestion(const QModelIndex &index) const;
    /// The row of suggestion `id` (column 0), invalid when there is none.
    QModelIndex indexOf(const QString &id) const;
    /// How many suggestions have `status` (of `kind` when given).
    int count(Suggestion::Status status) const;
    int count(Suggestion::Status status, Suggestion::Kind kind) const;
    /// The unresolved item a name-resolution suggestion targets (null when unknown).
    const SuggestionItem *item(const QString &itemId) const;

    /// "Description", "Grouping", "Name".
    static QString kindLabel(Suggestion::Kind kind);
    /// "descriptions", "groupings", "names" (for "Accept all …").
    static QString kindPlural(Suggestion::Kind kind);
    static QString statusLabel(Suggestion::Status status);
    /// A small round mark per status, drawn for the palette in use.
    static QIcon statusIcon(Suggestion::Status status);

    /// What the target column shows: class name, group name or the unresolved expression.
    QString targetText(const Suggestion &s) const;
    /// What the proposal column shows: description, member names or the candidate value.
    QString proposalText(const Suggestion &s) const;
    /// "file:line" of the first citation, "+n" when there are more.
    static QString evidenceText(const Suggestion &s);
    /// "deterministic" or "llm:model", as the origin column shows it.
    static QString originText(const Suggestion &s);

private:
    void rebuildItems();

    Document *m_document;
    QHash<QString, SuggestionItem> m_items;
};

} // namespace rosarch
