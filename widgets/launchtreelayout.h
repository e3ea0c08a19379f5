#pragma once

#include "core/launchdependencies.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

/// The rows of the launch tree: root launch-file instances → included instances, nodes and
/// unresolved actions in the order the file states them, namespace scopes as intermediate
/// rows, composable nodes under their container. Rows are numbered; a row's number is its
/// item index. Only the roots are made up front (with an index of who includes what, linear in
/// the size of the system); the rows inside a launch file are made the first time they are
/// asked for (ensureChildren), so a new stage 2 result costs the same on any system size.
class LaunchTreeLayout
{
public:
    enum class Kind
    {
        None,
        LaunchFile,
        Namespace,
        Node,
        Unresolved,
        Parameters, ///< a node's "Parameters" row (made by the model on demand, not laid out)
        Parameter,  ///< one parameter in effect under it (likewise)
    };
    struct Item
    {
        Kind kind = Kind::None;
        int ref = -1;      ///< index into instances or nodes; the unresolved entry's index
        int instance = -1; ///< the launch-file instance the row belongs to
        QString nameSpace; ///< namespace rows
        int parent = -1;
        int row = 0;
        QList<int> children;
        bool active = true;      ///< its own condition and its ancestors' hold
        int composableCount = 0; ///< node rows: composable nodes loaded into it
        bool built = true;       ///< launch-file rows: whether their children are made yet
        QString contextNs;       ///< launch-file rows: the scope it is included in
    };

    LaunchTreeLayout() = default;
    /// Lays out the roots of `launch`, which must outlive the layout (the model keeps both).
    explicit LaunchTreeLayout(const LaunchDependencies *launch);

    /// The rows made so far (a row's children exist once ensureChildren made them).
    const QList<Item> &items() const { return m_items; }
    const QList<int> &roots() const { return m_roots; }
    /// Makes the children of a launch-file row (nothing for other rows or when made).
    void ensureChildren(int item);
    /// Makes every row (a filter over the whole tree needs them all).
    void ensureAll();
    /// Whether the row has children, without making them where it can tell.
    bool hasChildren(int item);
    /// The row of a launch-file / node instance, making the rows on the way to it.
    int launchFileItem(const QString &instanceId);
    int nodeItem(const QString &nodeId);
    /// The launch-file row `item` lies in (itself for a launch-file row), -1 for none.
    int enclosingLaunchFile(int item) const;
    /// The innermost row whose evidence covers file:line; ties go to the row in the same
    /// launch-file instance as `nearItem` (a file included twice). -1 for none. Makes the
    /// rows on the way to it.
    int itemAt(const QString &file, int line, int nearItem = -1);

    /// The unresolved entries of `instance` that have no row of their own and that no child
    /// lists: they concern the include itself and show in its tooltip.
    static QList<Unresolved> attributeUnresolved(const LaunchFileInstance &instance,
                                                 const LaunchDependencies &launch);

private:
    /// One element a source line can lead to, in the file its evidence names.
    struct Candidate
    {
        Kind kind;
        int ref;      ///< instance, node or unresolved entry index
        int instance; ///< the launch-file instance it lies in (for a node: its owner)
        int order;    ///< the owner's place in the tree, so ties go to the first row
    };
    void claim(int root, QList<bool> *seenInstances, QList<bool> *seenNodes, int *order);
    /// `contextNs`: the namespace scope the instance is included in (shown by the parent).
    int addLaunchFile(int instance, int parentItem, const QString &contextNs);
    void buildChildren(int selfItem);
    int addItem(Item item, int parentItem);
    void indexEvidence();

    const LaunchDependencies *m_launch = nullptr;
    QList<Item> m_items;
    QList<int> m_roots;
    // Who shows what, decided once for the whole tree (the first includer in tree order):
    QList<QList<int>> m_includes; ///< instance → the instances shown under it
    QList<QList<int>> m_ownNodes; ///< instance → the node instances shown under it
    QList<int> m_instanceOwner;   ///< instance → the instance it is shown under (-1: a root)
    QList<int> m_nodeOwner;       ///< node → the instance it is shown under (-1: nowhere)
    QList<int> m_order;           ///< instance → its place in tree order
    QHash<QString, QList<int>> m_byParent;    ///< only while claiming
    QHash<QString, QList<int>> m_nodesByFile; ///< likewise
    QHash<QString, int> m_instanceIndex;
    QHash<QString, int> m_nodeIndex;
    QHash<QString, int> m_launchFiles;         ///< instance id → item (made so far)
    QHash<QString, int> m_nodes;               ///< node instance id → item (made so far)
    QHash<qint64, int> m_unresolvedItems;      ///< (instance << 32 | entry) → item (made so far)
    QHash<QString, QList<Candidate>> m_byFile; ///< made on the first itemAt
    bool m_evidenceIndexed = false;
};

} // namespace rosarch
