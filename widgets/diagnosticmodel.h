#pragma once

#include "core/diagnostic.h"
#include "project/findingmark.h"

#include <QAbstractItemModel>
#include <QHash>
#include <QMap>

#include <optional>

namespace rosarch {

class Document;

/// The findings of the last stage runs (stage 1's, then stage 2's and 3's) as a table a person
/// can work through: severity, kind, package, file, message and the number of systems a finding
/// was seen in. The model filters itself (severity, kind, package, text, hidden and accepted
/// findings) and groups the findings shown by kind or by package (group rows with counts);
/// sort it with a QSortFilterProxyModel on SortRole. Hide and accept push to the Document.
class DiagnosticModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column
    {
        SeverityColumn,
        KindColumn,
        PackageColumn,
        FileColumn,
        MessageColumn,
        ContextsColumn,
        ColumnCount
    };
    enum Role
    {
        SortRole = Qt::UserRole + 1, ///< what the column sorts by (rank, path and line, count)
        KeyRole,                     ///< the finding's stable key ("" for a group row)
        GroupRole,                   ///< true for a group row
    };
    enum class Grouping
    {
        None,
        Kind,
        Package
    };
    /// What is shown: every condition must hold. An empty code or package shows every one.
    struct Filter
    {
        bool errors = true;
        bool warnings = true;
        bool infos = true;
        QString code;
        QString package;
        QString text; ///< in the message, file, code, kind title or package (any case)
        bool showHidden = false;
        bool showAccepted = false;
        bool operator==(const Filter &) const = default;
    };

    explicit DiagnosticModel(Document *document, QObject *parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    const Filter &filter() const { return m_filter; }
    void setFilter(const Filter &filter);
    Grouping grouping() const { return m_grouping; }
    void setGrouping(Grouping grouping);

    /// The finding at `index` (null for a group row or an index of another model).
    const Diagnostic *diagnostic(const QModelIndex &index) const;
    /// The package a finding's file belongs to ("" when none).
    QString package(const QModelIndex &index) const;
    /// The hidden or accepted mark of the finding at `index` (by its key or an alias), if any.
    std::optional<FindingMark> mark(const QModelIndex &index) const;
    /// Every finding of the run, and those the filter shows.
    int total() const { return int(m_entries.size()); }
    int shown() const { return int(m_visible.size()); }
    /// How many findings of each code / package the rest of the filter shows (severities,
    /// text, the package or kind chosen, hidden and accepted): what the combo boxes offer.
    QMap<QString, int> codeCounts() const;
    QMap<QString, int> packageCounts() const;
    /// How many findings of `severity` there are among those not hidden or accepted (or shown).
    int severityCount(Diagnostic::Severity severity) const;

    /// Hides or accepts the findings at `indexes` (group rows: every finding shown in them) as
    /// one undo step; returns how many changed.
    int markFindings(const QModelIndexList &indexes, FindingMark::Status status,
                     const QString &reason = {});
    /// Removes the marks of the findings at `indexes` (they show again); returns how many.
    int restoreFindings(const QModelIndexList &indexes);

    static QString severityLabel(Diagnostic::Severity severity);

Q_SIGNALS:
    /// The findings, the filter, the grouping or the marks changed: counts and combos are stale.
    void findingsChanged();

private:
    struct Entry
    {
        const Diagnostic *diagnostic;
        mutable QString key; ///< made when first needed (keyOf): most are never asked for
        QString package;
        int mark = -1; ///< index into the project's finding marks, -1 = none
    };
    struct Group
    {
        QString label;
        QList<int> entries; ///< indexes into m_entries
    };
    void reload(); ///< the entries from the document, then rebuild()
    /// The entry's finding key (Diagnostic::key), made on first use.
    const QString &keyOf(const Entry &e) const;
    void rebuild(); ///< the marks, visibility and groups (no reset signals)
    void refresh(); ///< rebuild() inside a reset
    bool passes(const Entry &e, bool ignoreCode, bool ignorePackage) const;
    bool isShownMark(const Entry &e) const;
    int entryAt(const QModelIndex &index) const; ///< -1 for a group row
    QStringList keysAt(const QModelIndexList &indexes) const;

    Document *m_document;
    /// Stage 3's findings of the model as corrected (Document::accepted()): the checks of what a
    /// person sees in the diagram and exports. A copy, which the entries point into.
    QList<Diagnostic> m_architectureDiagnostics;
    QList<Entry> m_entries;
    QList<int> m_visible; ///< entries shown, in stage order
    QList<Group> m_groups;
    Filter m_filter;
    Grouping m_grouping = Grouping::None;
};

} // namespace rosarch
