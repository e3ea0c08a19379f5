#pragma once

#include "core/atomicnode.h"
#include "core/atomicnodelist.h"
#include "core/evidence.h"
#include "widgets/correctionindex.h"

#include <QAbstractItemModel>
#include <QList>
#include <QSet>

namespace rosarch {

class Document;
struct RosPackage;

/// The List of Atomic ROS Nodes as a tree: package → node → port, and after a node's ports a
/// "Parameters" row with the parameters it declares. Reads the Document;
/// editing a node's description pushes an undoable command instead of changing data here.
/// Shows the classes as corrected (blueprint §5): renamed and added elements in a quiet tint,
/// reviewed ones with a ✓, removed ones struck out where they were.
class AtomicNodeModel : public QAbstractItemModel
{
    Q_OBJECT
public:
    enum Column
    {
        NameColumn,
        TypeColumn,
        DetailsColumn,
        DescriptionColumn,
        ColumnCount
    };
    enum class ItemKind
    {
        None,
        Package,
        Node,
        Port,
        Parameters, ///< a node's "Parameters" row (only when it declares any)
        Parameter   ///< one declared parameter
    };
    enum Role
    {
        KindRole = Qt::UserRole + 1, ///< int(ItemKind)
        NodeIdRole,                  ///< "arc_3" for node and port rows
        PortIdRole,                  ///< "p1" for port rows
        ProvenanceRole,    ///< "recovered", "suggested", "corrected" or "removed" (node, port rows)
        ReviewedRole,      ///< bool: a person marked it reviewed
        ParameterNameRole, ///< the declared name of a parameter row
    };

    explicit AtomicNodeModel(Document *document, QObject *parent = nullptr);

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    /// data() before its text is made safe to show (visibleText: no control character raw).
    QVariant rawData(const QModelIndex &index, int role) const;
    bool setData(const QModelIndex &index, const QVariant &value, int role = Qt::EditRole) override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;

    ItemKind kind(const QModelIndex &index) const;
    /// The node of a node row, or the owning node of a port row.
    const AtomicNode *node(const QModelIndex &index) const;
    const Port *port(const QModelIndex &index) const;
    /// The declaration of a parameter row, or null.
    const ParameterDeclaration *parameter(const QModelIndex &index) const;
    /// True for a node or port a correction removed (shown struck out).
    bool isRemoved(const QModelIndex &index) const;
    /// The id of a node or port row ("arc_3", "arc_3/p1"); "" for a package or parameter row.
    QString elementId(const QModelIndex &index) const;
    /// Where the row's element comes from (invalid for rows without evidence).
    Evidence evidence(const QModelIndex &index) const;
    /// The stable key of a row (blueprint §5): its package's, class's or port's key; "id:" and
    /// the element id for what has none (a port a correction added, keys still being made).
    QString stableKey(const QModelIndex &index) const;
    /// The row stableKey() gave `key` (invalid when there is none now).
    QModelIndex indexOfStableKey(const QString &key) const;

    QModelIndex packageIndex(const QString &name, int column = 0) const;
    QModelIndex nodeIndex(const QString &nodeId, int column = 0) const;
    QModelIndex portIndex(const QString &nodeId, const QString &portId, int column = 0) const;
    /// The "Parameters" row of a node (invalid when it declares none).
    QModelIndex parametersIndex(const QString &nodeId, int column = 0) const;
    /// The row of the first parameter `nodeId` declares under `name`.
    QModelIndex parameterIndex(const QString &nodeId, const QString &name, int column = 0) const;
    /// The innermost element whose evidence covers file:line (a port before its node).
    QModelIndex indexAt(const QString &file, int line) const;

    /// Shows a proposed description of one node (a pending suggestion) in the description
    /// column, marked as suggested; the model is not changed. An empty id ends the preview.
    void setDescriptionPreview(const QString &nodeId, const QString &description);

private:
    struct PackageRow
    {
        QString name;
        int package = -1; ///< index into AtomicNodeList::packages, -1 when only nodes name it
        QList<int> nodes; ///< indexes into AtomicNodeList::nodes
    };
    struct NodeLocation
    {
        int packageRow = 0;
        int row = 0;
    };

    void rebuild(bool merge = true);
    AtomicNodeList merged();
    void onCorrectionsChanged();
    QVariant marksData(const QString &id, const Marks &marks, int column, int role) const;
    void onNodeChanged(const QString &nodeId);
    const RosPackage *package(const PackageRow &row) const;
    int nodeListIndex(const QModelIndex &index) const;
    /// The index of a row of `kind` whose parent `parent` locates (a package row, a node's
    /// index in the list); invalid when an internal id cannot hold `parent`.
    QModelIndex makeIndex(int row, int column, ItemKind kind, qsizetype parent = 0) const;

    QVariant packageData(const PackageRow &row, int column, int role) const;
    QVariant nodeData(const AtomicNode &node, int column, int role) const;
    QVariant portData(const AtomicNode &node, const Port &port, int column, int role) const;
    QVariant parametersData(const AtomicNode &node, int column, int role) const;
    /// The plugin classes the launched instances of class `classId` load, by class name.
    QList<const AtomicNode *> loadedPlugins(const QString &classId) const;
    QVariant parameterData(const AtomicNode &node, const ParameterDeclaration &parameter,
                           int column, int role) const;

    Document *m_document;
    AtomicNodeList m_nodes;  ///< as corrected, with removed elements where they were
    QSet<QString> m_removed; ///< ids of removed nodes and ports ("arc_3", "arc_3/p1")
    CorrectionIndex m_index;
    QString m_previewNodeId;
    QString m_previewDescription;
    QList<PackageRow> m_packages;
    QList<NodeLocation> m_nodeLocations; ///< parallel to AtomicNodeList::nodes
};

} // namespace rosarch
