#include "launchtreelayout.h"
#include "launchtreetext.h"

#include <QSet>

#include <algorithm>
#include <functional>
#include <limits>

namespace rosarch {

namespace {

/// Lines an evidence covers; a missing end means the start line only.
bool covers(const Evidence &e, const QString &file, int line, int *span)
{
    if (!e.isValid() || e.file != file)
        return false;
    const int end = std::max(e.endLine, e.line);
    if (line < e.line || line > end)
        return false;
    *span = end - e.line;
    return true;
}

bool isRootNamespace(const QString &ns)
{
    return ns.isEmpty() || ns == QLatin1String("/");
}

/// The innermost namespace scope of `instance` that lists `id`, "" when none does.
QString innermostScope(const LaunchFileInstance &instance, const QString &id)
{
    QString best;
    for (auto it = instance.namespaces.cbegin(); it != instance.namespaces.cend(); ++it)
        if (!isRootNamespace(it.key()) && it.value().contains(id) && it.key().size() > best.size())
            best = it.key();
    return best;
}

enum class Placement
{
    Row,       ///< stands on its own line inside the file: an OpaqueFunction, an unknown action
    Attribute, ///< concerns the include itself (or a child that does not list it)
    Child,     ///< a child lists it already
};

Placement placement(const Unresolved &u, const LaunchFileInstance &instance,
                    const LaunchDependencies &launch)
{
    if (instance.file.isEmpty() || !u.evidence.isValid() || u.evidence.file != instance.file)
        return Placement::Attribute;
    int span = 0;
    if (instance.evidence.file == instance.file &&
        covers(instance.evidence, u.evidence.file, u.evidence.line, &span) && span == 0)
        return Placement::Attribute;
    bool covered = false;
    for (const QString &id : instance.nodes) {
        if (const NodeInstance *n = launch.node(id);
            n && covers(n->evidence, u.evidence.file, u.evidence.line, &span)) {
            if (n->unresolved.contains(u))
                return Placement::Child;
            covered = true;
        }
    }
    for (const QString &id : instance.includedLaunchFiles) {
        if (const LaunchFileInstance *i = launch.instance(id);
            i && covers(i->evidence, u.evidence.file, u.evidence.line, &span)) {
            if (i->unresolved.contains(u))
                return Placement::Child;
            covered = true;
        }
    }
    return covered ? Placement::Attribute : Placement::Row;
}

} // namespace

QList<Unresolved> LaunchTreeLayout::attributeUnresolved(const LaunchFileInstance &instance,
                                                        const LaunchDependencies &launch)
{
    QList<Unresolved> out;
    for (const Unresolved &u : instance.unresolved)
        if (placement(u, instance, launch) == Placement::Attribute)
            out << u;
    return out;
}

LaunchTreeLayout::LaunchTreeLayout(const LaunchDependencies &launch) : m_launch(&launch)
{
    m_seenInstances.fill(false, launch.instances.size());
    m_seenNodes.fill(false, launch.nodes.size());
    for (int i = 0; i < launch.instances.size(); ++i) {
        const QString &parentId = launch.instances[i].parentId;
        if (!m_seenInstances[i] && (parentId.isEmpty() || !launch.instance(parentId))) {
            m_seenInstances[i] = true;
            buildLaunchFile(i, -1, {});
        }
    }
    // Instances only reachable through a cycle of parents still get shown.
    for (int i = 0; i < launch.instances.size(); ++i) {
        if (!m_seenInstances[i]) {
            m_seenInstances[i] = true;
            buildLaunchFile(i, -1, {});
        }
    }
    m_launch = nullptr;
    m_seenInstances.clear();
    m_seenNodes.clear();
}

int LaunchTreeLayout::addItem(Item item, int parentItem)
{
    const int id = int(m_items.size());
    item.parent = parentItem;
    if (parentItem >= 0) {
        item.active = item.active && m_items[parentItem].active;
        item.row = int(m_items[parentItem].children.size());
        m_items[parentItem].children.append(id);
    } else {
        item.row = int(m_roots.size());
        m_roots.append(id);
    }
    m_items.append(item);
    return id;
}

void LaunchTreeLayout::buildLaunchFile(int instance, int parentItem, const QString &contextNs)
{
    const LaunchDependencies &launch = *m_launch;
    const LaunchFileInstance &lf = launch.instances[instance];
    Item self;
    self.kind = Kind::LaunchFile;
    self.ref = instance;
    self.instance = instance;
    self.active = lf.active;
    const int selfItem = addItem(self, parentItem);
    m_launchFiles.insert(lf.id, selfItem);

    struct Child
    {
        Kind kind;
        int ref;
        Evidence evidence;
        QString id;
    };
    QList<Child> children;
    QStringList includeIds = lf.includedLaunchFiles;
    for (const LaunchFileInstance &other : launch.instances)
        if (other.parentId == lf.id && !includeIds.contains(other.id))
            includeIds << other.id;
    for (const QString &id : std::as_const(includeIds)) {
        for (int i = 0; i < launch.instances.size(); ++i) {
            if (launch.instances[i].id == id && !m_seenInstances[i]) {
                m_seenInstances[i] = true;
                children.append({Kind::LaunchFile, i, launch.instances[i].evidence, id});
            }
        }
    }
    QStringList nodeIds = lf.nodes;
    for (const NodeInstance &n : launch.nodes)
        if (n.launchFileId == lf.id && !nodeIds.contains(n.id))
            nodeIds << n.id;
    for (const QString &id : std::as_const(nodeIds)) {
        for (int i = 0; i < launch.nodes.size(); ++i) {
            if (launch.nodes[i].id == id && !m_seenNodes[i]) {
                m_seenNodes[i] = true;
                children.append({Kind::Node, i, launch.nodes[i].evidence, id});
            }
        }
    }
    for (int k = 0; k < lf.unresolved.size(); ++k)
        if (placement(lf.unresolved[k], lf, launch) == Placement::Row)
            children.append({Kind::Unresolved, k, lf.unresolved[k].evidence, {}});
    // In the order the file states them.
    std::stable_sort(children.begin(), children.end(), [](const Child &a, const Child &b) {
        const int la = a.evidence.isValid() ? a.evidence.line : std::numeric_limits<int>::max();
        const int lb = b.evidence.isValid() ? b.evidence.line : std::numeric_limits<int>::max();
        return la != lb ? la < lb : a.evidence.column < b.evidence.column;
    });

    // Composable nodes go under their container when this file starts it too; the container
    // is named by id, or by name when the analyzer could not find it.
    QHash<QString, int> localNodes;
    for (const Child &c : std::as_const(children)) {
        if (c.kind != Kind::Node)
            continue;
        const NodeInstance &n = launch.nodes[c.ref];
        localNodes.insert(n.id, c.ref);
        localNodes.insert(LaunchTreeText::fullyQualifiedName(n), c.ref);
        if (!localNodes.contains(n.nodeName))
            localNodes.insert(n.nodeName, c.ref);
    }
    const auto containerOf = [&](int nodeRef) {
        const NodeInstance &n = launch.nodes[nodeRef];
        const int c = n.container.isEmpty() ? -1 : localNodes.value(n.container, -1);
        return c == nodeRef ? -1 : c;
    };

    QHash<QString, int> scopeItems;
    std::function<int(const QString &)> ensureScope = [&](const QString &scope) -> int {
        // The scope this file was included in is the parent's row already.
        if (isRootNamespace(scope) || scope == contextNs)
            return selfItem;
        if (const auto it = scopeItems.constFind(scope); it != scopeItems.cend())
            return *it;
        QString outer; // the closest enclosing scope of the same file
        for (auto it = lf.namespaces.cbegin(); it != lf.namespaces.cend(); ++it)
            if (!isRootNamespace(it.key()) && it.key() != scope &&
                scope.startsWith(it.key() + QLatin1Char('/')) && it.key().size() > outer.size())
                outer = it.key();
        const int parent = outer.isEmpty() ? selfItem : ensureScope(outer);
        Item ns;
        ns.kind = Kind::Namespace;
        ns.instance = instance;
        ns.nameSpace = scope;
        const int item = addItem(ns, parent);
        scopeItems.insert(scope, item);
        return item;
    };

    const auto addNode = [&](const Child &c, int parent) {
        Item item;
        item.kind = Kind::Node;
        item.ref = c.ref;
        item.instance = instance;
        item.active = launch.nodes[c.ref].active;
        const int id = addItem(item, parent);
        m_nodes.insert(c.id, id);
        return id;
    };
    QHash<int, int> nodeItemByRef;
    for (const Child &c : std::as_const(children)) {
        if (c.kind == Kind::Node && containerOf(c.ref) >= 0)
            continue;
        const QString scope = c.id.isEmpty() ? QString() : innermostScope(lf, c.id);
        const int parent = ensureScope(scope);
        if (c.kind == Kind::LaunchFile) {
            buildLaunchFile(c.ref, parent, scope.isEmpty() ? contextNs : scope);
        } else if (c.kind == Kind::Node) {
            nodeItemByRef.insert(c.ref, addNode(c, parent));
        } else {
            Item item;
            item.kind = c.kind;
            item.ref = c.ref;
            item.instance = instance;
            addItem(item, parent);
        }
    }
    for (const Child &c : std::as_const(children)) {
        if (c.kind != Kind::Node || containerOf(c.ref) < 0)
            continue;
        const int parent = nodeItemByRef.value(containerOf(c.ref), selfItem);
        addNode(c, parent);
        if (parent != selfItem)
            ++m_items[parent].composableCount;
    }
}

int LaunchTreeLayout::enclosingLaunchFile(int item) const
{
    while (item >= 0 && item < m_items.size() && m_items[item].kind != Kind::LaunchFile)
        item = m_items[item].parent;
    return item < m_items.size() ? item : -1;
}

int LaunchTreeLayout::itemAt(const LaunchDependencies &launch, const QString &file, int line,
                             int nearItem) const
{
    const int nearFile = enclosingLaunchFile(nearItem);
    int best = -1;
    int bestSpan = std::numeric_limits<int>::max();
    bool bestNear = false;
    for (int i = 0; i < m_items.size(); ++i) {
        const Item &item = m_items[i];
        int span = 0;
        bool hit = false;
        int context = enclosingLaunchFile(i);
        switch (item.kind) {
        case Kind::LaunchFile: {
            const LaunchFileInstance &lf = launch.instances[item.ref];
            hit = covers(lf.evidence, file, line, &span);
            if (hit && lf.file != file) {
                context = enclosingLaunchFile(item.parent); // an include line: the includer's
            } else if (!hit && lf.file == file && line > 0) {
                // Any other line of a launch file belongs to the file, below all its items.
                hit = true;
                span = std::numeric_limits<int>::max() - 1;
            }
            break;
        }
        case Kind::Node:
            hit = covers(launch.nodes[item.ref].evidence, file, line, &span);
            break;
        case Kind::Unresolved:
            hit = covers(launch.instances[item.instance].unresolved[item.ref].evidence, file, line,
                         &span);
            break;
        case Kind::Namespace:
        case Kind::Parameters: // not laid out: the model makes them
        case Kind::Parameter:
        case Kind::None:
            break;
        }
        if (!hit)
            continue;
        const bool isNear = nearFile >= 0 && context == nearFile;
        if (span < bestSpan || (span == bestSpan && isNear && !bestNear)) {
            best = i;
            bestSpan = span;
            bestNear = isNear;
        }
    }
    return best;
}

} // namespace rosarch
