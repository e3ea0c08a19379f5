#pragma once

#include "launchdependencies.h"

#include <QHash>
#include <QList>
#include <QString>

namespace rosarch {

/// The rows of the launch tree, computed once per stage 2 result: root launch-file instances
/// → included instances, nodes and unresolved actions in the order the file states them,
/// namespace scopes as intermediate rows, composable nodes under their container.
/// Rows are numbered; a row's number is its item index.
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
    };

    LaunchTreeLayout() = default;
    explicit LaunchTreeLayout(const LaunchDependencies &launch);

    const QList<Item> &items() const { return m_items; }
    const QList<int> &roots() const { return m_roots; }
    int launchFileItem(const QString &instanceId) const
    {
        return m_launchFiles.value(instanceId, -1);
    }
    int nodeItem(const QString &nodeId) const { return m_nodes.value(nodeId, -1); }
    /// The launch-file row `item` lies in (itself for a launch-file row), -1 for none.
    int enclosingLaunchFile(int item) const;
    /// The innermost row whose evidence covers file:line; ties go to the row in the same
    /// launch-file instance as `nearItem` (a file included twice). -1 for none.
    int itemAt(const LaunchDependencies &launch, const QString &file, int line,
               int nearItem = -1) const;

    /// The unresolved entries of `instance` that have no row of their own and that no child
    /// lists: they concern the include itself and show in its tooltip.
    static QList<Unresolved> attributeUnresolved(const LaunchFileInstance &instance,
                                                 const LaunchDependencies &launch);

private:
    /// `contextNs`: the namespace scope the instance is included in (shown by the parent).
    void buildLaunchFile(int instance, int parentItem, const QString &contextNs);
    int addItem(Item item, int parentItem);

    const LaunchDependencies *m_launch = nullptr; ///< only while building
    QList<Item> m_items;
    QList<int> m_roots;
    QList<bool> m_seenInstances;
    QList<bool> m_seenNodes;
    QHash<QString, int> m_launchFiles; ///< instance id → item
    QHash<QString, int> m_nodes;       ///< node instance id → item
};

} // namespace rosarch
