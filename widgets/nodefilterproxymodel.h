#pragma once

#include <QHash>
#include <QMetaObject>
#include <QRegularExpression>
#include <QSortFilterProxyModel>
#include <QStringList>

class QTimer;

#include <vector>

namespace rosarch {

/// Filters a tree by the text of some columns (the node tree: name and type); keeps the
/// ancestors of a match and all rows under a matching row, so a matching node shows its ports.
///
/// A filter over a large tree (the launch tree of a navigation stack) must follow typing:
/// each row's text is read from the source model once, and whether a row matches, has a
/// matching ancestor or a matching descendant is found once per filter and kept, where the
/// proxy's own recursive filtering asks about a row again for every ancestor. Rows are told
/// apart by their internal id and row, which identifies a row both in models whose internal id
/// names the row and in those whose id names its parent. Any change of the source model
/// forgets them.
class NodeFilterProxyModel : public QSortFilterProxyModel
{
    Q_OBJECT
public:
    explicit NodeFilterProxyModel(QObject *parent = nullptr);

    void setSourceModel(QAbstractItemModel *sourceModel) override;
    /// The columns whose text is matched (default: the node tree's name and type).
    void setFilterColumns(const QList<int> &columns);
    /// Whether the row's own text matches the filter (not only a descendant's, or its
    /// parent's): the rows a filter is looking for.
    bool matchesItself(const QModelIndex &proxyIndex) const;

    /// Filters by `text` (case-insensitive, literal) as the person types: the rows are read
    /// and matched in slices of a few milliseconds between events, and the filter is applied
    /// in one step when every row is known (at once on a small tree, and at once for ""). A
    /// newer text replaces one still being matched. filterApplied() tells when it applied.
    void setFilterTextInSlices(const QString &text);
    /// True while a text given to setFilterTextInSlices() is still being matched.
    bool isFiltering() const { return m_pending.active; }

Q_SIGNALS:
    /// The filter of setFilterTextInSlices() is applied.
    void filterApplied();

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override;

private:
    /// What is known of one source row; the flags hold for filter `generation` only.
    struct Row
    {
        QStringList texts;      ///< one per filter column; read once
        int generation = -1;    ///< the filter the flags below were found for
        signed char self = -1;  ///< its own text matches (-1: not known yet)
        signed char above = -1; ///< itself or an ancestor matches
        signed char below = -1; ///< a descendant matches
        int parent = -2;        ///< the parent's slot, -1 for a top row (-2: not known yet)
    };
    /// Reads and matches rows for the pending text for about `budgetMs`; applies the filter
    /// when all are done.
    void continueFiltering(int budgetMs);
    void applyPending();
    /// The slot of a source row in m_rows (made when new), flags reset for a new filter.
    int slotOf(const QModelIndex &sourceIndex) const;
    bool selfMatches(const QModelIndex &sourceIndex) const;
    bool selfOrAncestorMatches(const QModelIndex &sourceIndex) const;
    bool descendantMatches(const QModelIndex &sourceIndex) const;
    /// Starts a new filter generation when the filter differs from the one rows were matched
    /// against; true when there is a filter at all.
    bool followFilter() const;
    /// Forgets the rows' texts and matches (the source model changed).
    void forgetRows();

    QList<int> m_columns;
    mutable QHash<std::pair<quintptr, int>, int> m_slots; ///< internal id and row → m_rows
    mutable std::vector<Row> m_rows;
    mutable QRegularExpression m_matchedRe; ///< the filter the flags were found for
    mutable int m_generation = 0;
    bool m_holdFilter = false; ///< rows keep their answers while the filter property changes
    QList<QMetaObject::Connection> m_sourceConnections;

    /// The walk over every source row (depth first, resumable) and the matching that follow
    /// setFilterTextInSlices().
    struct Frame
    {
        QModelIndex index; ///< column 0; invalid for the root
        int slot = -1;
        int next = 0; ///< the next child to visit
    };
    struct Pending
    {
        bool active = false;
        QString text;
        std::vector<Frame> walk; ///< empty with walked set: every row has a slot and its texts
        bool walked = false;
        size_t matched = 0;            ///< rows matched so far, by slot
        std::vector<signed char> self; ///< whether each row's own text matches `text`
    };
    Pending m_pending;
    QTimer *m_slices;
    static constexpr int kSliceMs = 8;
};

} // namespace rosarch
