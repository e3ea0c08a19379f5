#pragma once

#include "core/evidence.h"
#include "core/launchdependencies.h"
#include "widgets/correctionindex.h"
#include "widgets/launchtreelayout.h"
#include "widgets/treeindexid.h"

#include <QAbstractItemModel>
#include <QSet>

namespace rosarch {

class Document;

/// The Launch File Dependency Description as a tree: root launch-file instances → included
/// instances → node instances, with namespace scopes as intermediate rows, composable nodes
/// under their container and unresolved actions at the line they stand on. Read-only. Shows
/// the node instances as corrected (blueprint §5): renamed and added ones in a quiet tint,
/// reviewed ones with a ✓, removed ones struck out where they were.
class LaunchTreeModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column
    {
        NameColumn,
        NamespaceColumn,
        ClassColumn, ///< before the executable: the link to the atomic nodes stays in sight
        ExecutableColumn,
        DetailsColumn,
        ColumnCount
    };
    using ItemKind = LaunchTreeLayout::Kind;
    enum Role
    {
        KindRole = Qt::UserRole + 1, ///< int(ItemKind)
        InstanceIdRole,              ///< "lf2" or "n3"; the owning launch file for other rows
        ClassIdRole,                 ///< node rows: the atomic node's id ("" when unknown)
        ActiveRole,                  ///< false when a condition (here or above) is false
        ProvenanceRole, ///< node rows: "recovered", "suggested", "corrected" or "removed"
        ReviewedRole,   ///< node rows: a person marked it reviewed
    };

    explicit LaunchTreeModel(Document *document, QObject *parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    bool hasChildren(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    /// data() before its text is made safe to show (visibleText: no control character raw).
    QVariant rawData(const QModelIndex &index, int role) const;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    ItemKind kind(const QModelIndex &index) const;
    /// The launch-file instance of a launch-file row, or the one a row belongs to.
    const LaunchFileInstance *launchFile(const QModelIndex &index) const;
    const NodeInstance *node(const QModelIndex &index) const;
    const Unresolved *unresolved(const QModelIndex &index) const;
    /// A parameter row's parameter (null for other rows).
    const ParameterSetting *parameter(const QModelIndex &index) const;
    /// Where the row's element comes from (invalid for namespace rows).
    Evidence evidence(const QModelIndex &index) const;
    /// True for a node instance a correction removed (shown struck out).
    bool isRemoved(const QModelIndex &index) const;
    /// The stable key of a node or launch-file row (blueprint §5): its instance's key; "id:" and
    /// the instance id for what has none (a part a correction added, keys still being made);
    /// "" for other rows.
    QString stableKey(const QModelIndex &index) const;
    /// The row stableKey() gave `key` (invalid when there is none now).
    QModelIndex indexOfStableKey(const QString &key) const;
    /// The corrections of an element by id ("n3", "lf2"), one line each ("" for none).
    QString correctionSummary(const QString &id) const;
    /// Whether the row's condition and those of all its ancestors hold.
    bool isActive(const QModelIndex &index) const;

    /// How many rows are made so far: a launch file's rows are made when first asked for.
    int rowsMade() const { return int(m_layout.items().size()); }

    QModelIndex launchFileIndex(const QString &instanceId, int column = 0) const;
    QModelIndex nodeIndex(const QString &nodeId, int column = 0) const;
    /// The innermost row whose evidence covers file:line. A file included twice has its lines
    /// in two instances; then the one `near` (a row, usually the current one) lies in wins.
    QModelIndex indexAt(const QString &file, int line, const QModelIndex &near = {}) const;

private:
    using Item = LaunchTreeLayout::Item;

    void rebuild();
    LaunchDependencies merged();
    void onCorrectionsChanged();
    int itemOf(const QModelIndex &index) const;
    QModelIndex indexOfItem(int item, int column) const;
    /// Whether stage 1 found `package` in the workspace (else its classes are not analysed).
    bool isWorkspacePackage(const QString &package) const;

    QVariant launchFileData(const Item &item, int column, int role) const;
    QVariant namespaceData(const Item &item, int column, int role) const;
    QVariant nodeData(const Item &item, int column, int role) const;
    QVariant unresolvedData(const Item &item, int column, int role) const;
    // A node's parameters in effect are rows made on demand (a navigation stack has ten
    // thousands): a "Parameters" row after the node's children, and one row per parameter.
    // A row's internal id tags which of the three it is: a row of the layout (its item), a
    // "Parameters" row (its node's item) or a parameter row (its node's item above the
    // parameter's index, in the low kParameterBits).
    enum class RowTag
    {
        Item,
        Parameters,
        Parameter
    };
    /// 16 million parameters a node; 4096 where quintptr has 32 bits, to leave items 18 bits.
    static constexpr int kParameterBits = QT_POINTER_SIZE == 8 ? 24 : 12;
    using RowId = TreeIndexId<RowTag, 2, kParameterBits>;
    /// The index of a row of the layout (`item`), of a node's "Parameters" row (`item` is the
    /// node's) or of its parameter `parameter`; invalid when an internal id cannot hold them.
    QModelIndex makeIndex(int row, int column, RowTag tag, qsizetype item,
                          qsizetype parameter = 0) const;
    /// How many parameter rows the node item `item` shows under its "Parameters" row (0 for
    /// other items, and for a node with more than internal ids can number).
    int parameterCount(int item) const;
    /// The node item of a "Parameters" row or a parameter row (-1 for other rows); `*k` is the
    /// parameter's index (-1 for the "Parameters" row).
    int parameterRowOf(const QModelIndex &index, int *k) const;
    const NodeInstance *nodeOfItem(int item) const;
    QVariant parameterData(const QModelIndex &index, int role) const;

    Document *m_document;
    LaunchDependencies m_launch; ///< as corrected, with removed instances where they were
    QSet<QString> m_removed;     ///< ids of removed node instances
    CorrectionIndex m_index;
    /// Rows are made as they are asked for (rowCount, index, a lookup): the cache is mutable.
    mutable LaunchTreeLayout m_layout;
};

} // namespace rosarch
