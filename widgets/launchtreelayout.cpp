#include "widgets/launchtreelayout.h"
#include "widgets/evidencelines.h"
#include "widgets/launchtreetext.h"

#include <QSet>

#include <algorithm>
#include <functional>
#include <limits>

namespace rosarch {

namespace {

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
        coversLine(instance.evidence, u.evidence.file, u.evidence.line, &span) && span == 0)
        return Placement::Attribute;
    bool covered = false;
    for (const QString &id : instance.nodes) {
        if (const NodeInstance *n = launch.node(id);
            n && coversLine(n->evidence, u.evidence.file, u.evidence.line, &span)) {
            if (n->unresolved.contains(u))
                return Placement::Child;
            covered = true;
        }
    }
    for (const QString &id : instance.includedLaunchFiles) {
        if (const LaunchFileInstance *i = launch.instance(id);
            i && coversLine(i->evidence, u.evidence.file, u.evidence.line, &span)) {
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

LaunchTreeLayout::LaunchTreeLayout(const LaunchDependencies *launch) : m_launch(launch)
{
    const qsizetype instances = launch->instances.size();
    const qsizetype nodes = launch->nodes.size();
    m_includes.resize(instances);
    m_ownNodes.resize(instances);
    m_instanceOwner.fill(-1, instances);
    m_nodeOwner.fill(-1, nodes);
    m_order.fill(0, instances);
    for (int i = int(instances) - 1; i >= 0; --i) // the first of equal ids wins
        m_instanceIndex.insert(launch->instances[i].id, i);
    for (int i = int(nodes) - 1; i >= 0; --i)
        m_nodeIndex.insert(launch->nodes[i].id, i);

    for (int i = 0; i < instances; ++i)
        if (!launch->instances[i].parentId.isEmpty())
            m_byParent[launch->instances[i].parentId] << i;
    for (int i = 0; i < nodes; ++i)
        if (!launch->nodes[i].launchFileId.isEmpty())
            m_nodesByFile[launch->nodes[i].launchFileId] << i;
    QList<bool> seenInstances(instances, false);
    QList<bool> seenNodes(nodes, false);
    QList<int> rootInstances;
    int order = 0;
    for (int i = 0; i < instances; ++i) {
        const QString &parentId = launch->instances[i].parentId;
        if (!seenInstances[i] && (parentId.isEmpty() || !m_instanceIndex.contains(parentId))) {
            seenInstances[i] = true;
            rootInstances << i;
            claim(i, &seenInstances, &seenNodes, &order);
        }
    }
    // Instances only reachable through a cycle of parents still get shown.
    for (int i = 0; i < instances; ++i) {
        if (!seenInstances[i]) {
            seenInstances[i] = true;
            rootInstances << i;
            claim(i, &seenInstances, &seenNodes, &order);
        }
    }
    m_byParent.clear();
    m_nodesByFile.clear();
    for (int i : std::as_const(rootInstances))
        addLaunchFile(i, -1, {});
}

// Who shows which instance and node, in the order the full tree lists them: an instance lists
// its includes and then its nodes; an include already listed elsewhere is not listed again.
void LaunchTreeLayout::claim(int root, QList<bool> *seenInstances, QList<bool> *seenNodes,
                             int *order)
{
    const LaunchDependencies &launch = *m_launch;
    const QHash<QString, QList<int>> &byParent = m_byParent;
    const QHash<QString, QList<int>> &nodesByFile = m_nodesByFile;
    QList<int> stack{root};
    while (!stack.isEmpty()) {
        const int at = stack.takeLast();
        m_order[at] = (*order)++;
        const LaunchFileInstance &lf = launch.instances[at];
        QList<int> includes;
        QSet<QString> listed;
        const auto take = [&](const QString &id) {
            if (listed.contains(id))
                return;
            listed.insert(id);
            const int i = m_instanceIndex.value(id, -1);
            if (i < 0 || (*seenInstances)[i])
                return;
            (*seenInstances)[i] = true;
            m_instanceOwner[i] = at;
            includes << i;
        };
        for (const QString &id : lf.includedLaunchFiles)
            take(id);
        for (int i : byParent.value(lf.id))
            take(launch.instances[i].id);
        QSet<QString> listedNodes;
        const auto takeNode = [&](const QString &id) {
            if (listedNodes.contains(id))
                return;
            listedNodes.insert(id);
            const int n = m_nodeIndex.value(id, -1);
            if (n < 0 || (*seenNodes)[n])
                return;
            (*seenNodes)[n] = true;
            m_nodeOwner[n] = at;
            m_ownNodes[at] << n;
        };
        for (const QString &id : lf.nodes)
            takeNode(id);
        for (int n : nodesByFile.value(lf.id))
            takeNode(launch.nodes[n].id);
        m_includes[at] = includes;
        // Visited in the order the file states them, the first first.
        QList<int> sorted = includes;
        std::stable_sort(sorted.begin(), sorted.end(), [&](int a, int b) {
            const Evidence &ea = launch.instances[a].evidence;
            const Evidence &eb = launch.instances[b].evidence;
            const int la = ea.isValid() ? ea.line : std::numeric_limits<int>::max();
            const int lb = eb.isValid() ? eb.line : std::numeric_limits<int>::max();
            return la != lb ? la < lb : ea.column < eb.column;
        });
        for (auto it = sorted.crbegin(); it != sorted.crend(); ++it)
            stack << *it;
    }
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

int LaunchTreeLayout::addLaunchFile(int instance, int parentItem, const QString &contextNs)
{
    Item self;
    self.kind = Kind::LaunchFile;
    self.ref = instance;
    self.instance = instance;
    self.active = m_launch->instances[instance].active;
    self.built = false;
    self.contextNs = contextNs;
    const int item = addItem(self, parentItem);
    m_launchFiles.insert(m_launch->instances[instance].id, item);
    return item;
}

void LaunchTreeLayout::ensureChildren(int item)
{
    if (item < 0 || item >= m_items.size() || m_items[item].built)
        return;
    m_items[item].built = true;
    buildChildren(item);
}

void LaunchTreeLayout::ensureAll()
{
    for (int i = 0; i < m_items.size(); ++i) // the list grows as it goes
        ensureChildren(i);
}

bool LaunchTreeLayout::hasChildren(int item)
{
    if (item < 0 || item >= m_items.size())
        return false;
    const Item &it = m_items[item];
    if (!it.built && it.kind == Kind::LaunchFile &&
        (!m_includes[it.instance].isEmpty() || !m_ownNodes[it.instance].isEmpty()))
        return true;
    ensureChildren(item); // only unresolved actions could be rows: see
    return !m_items[item].children.isEmpty();
}

int LaunchTreeLayout::launchFileItem(const QString &instanceId)
{
    if (const auto it = m_launchFiles.constFind(instanceId); it != m_launchFiles.cend())
        return *it;
    const int instance = m_instanceIndex.value(instanceId, -1);
    if (instance < 0)
        return -1;
    QList<int> chain; // the includers, innermost first
    for (int i = m_instanceOwner[instance]; i >= 0 && chain.size() < m_includes.size();
         i = m_instanceOwner[i])
        chain << i;
    for (auto it = chain.crbegin(); it != chain.crend(); ++it)
        ensureChildren(m_launchFiles.value(m_launch->instances[*it].id, -1));
    return m_launchFiles.value(instanceId, -1);
}

int LaunchTreeLayout::nodeItem(const QString &nodeId)
{
    if (const auto it = m_nodes.constFind(nodeId); it != m_nodes.cend())
        return *it;
    const int node = m_nodeIndex.value(nodeId, -1);
    if (node < 0 || m_nodeOwner[node] < 0)
        return -1;
    ensureChildren(launchFileItem(m_launch->instances[m_nodeOwner[node]].id));
    return m_nodes.value(nodeId, -1);
}

void LaunchTreeLayout::buildChildren(int selfItem)
{
    const LaunchDependencies &launch = *m_launch;
    const int instance = m_items[selfItem].instance;
    const QString contextNs = m_items[selfItem].contextNs;
    const LaunchFileInstance &lf = launch.instances[instance];

    struct Child
    {
        Kind kind;
        int ref;
        Evidence evidence;
        QString id;
    };
    QList<Child> children;
    for (int i : std::as_const(m_includes[instance]))
        children.append(
            {Kind::LaunchFile, i, launch.instances[i].evidence, launch.instances[i].id});
    for (int i : std::as_const(m_ownNodes[instance]))
        children.append({Kind::Node, i, launch.nodes[i].evidence, launch.nodes[i].id});
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
            addLaunchFile(c.ref, parent, scope.isEmpty() ? contextNs : scope);
        } else if (c.kind == Kind::Node) {
            nodeItemByRef.insert(c.ref, addNode(c, parent));
        } else {
            Item item;
            item.kind = c.kind;
            item.ref = c.ref;
            item.instance = instance;
            m_unresolvedItems.insert((qint64(instance) << 32) | c.ref, addItem(item, parent));
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

void LaunchTreeLayout::indexEvidence()
{
    m_evidenceIndexed = true;
    const LaunchDependencies &launch = *m_launch;
    for (int i = 0; i < launch.instances.size(); ++i) {
        const LaunchFileInstance &lf = launch.instances[i];
        const Candidate self{Kind::LaunchFile, i, i, m_order[i]};
        if (lf.evidence.isValid())
            m_byFile[lf.evidence.file] << self;
        if (!lf.file.isEmpty() && lf.file != lf.evidence.file)
            m_byFile[lf.file] << self; // any line of the file belongs to it
        for (int k = 0; k < lf.unresolved.size(); ++k)
            if (lf.unresolved[k].evidence.isValid())
                m_byFile[lf.unresolved[k].evidence.file]
                    << Candidate{Kind::Unresolved, k, i, m_order[i]};
    }
    for (int n = 0; n < launch.nodes.size(); ++n) {
        const int owner = m_nodeOwner[n];
        if (owner >= 0 && launch.nodes[n].evidence.isValid())
            m_byFile[launch.nodes[n].evidence.file]
                << Candidate{Kind::Node, n, owner, m_order[owner]};
    }
    // Ties go to the row the tree lists first: its launch file, then its rows in line order.
    for (QList<Candidate> &list : m_byFile)
        std::stable_sort(list.begin(), list.end(), [](const Candidate &a, const Candidate &b) {
            if (a.order != b.order)
                return a.order < b.order;
            return (a.kind == Kind::LaunchFile) > (b.kind == Kind::LaunchFile);
        });
}

int LaunchTreeLayout::itemAt(const QString &file, int line, int nearItem)
{
    if (!m_evidenceIndexed)
        indexEvidence();
    const LaunchDependencies &launch = *m_launch;
    const int nearFile = enclosingLaunchFile(nearItem);
    const int nearInstance = nearFile >= 0 ? m_items[nearFile].instance : -1;
    const Candidate *best = nullptr;
    int bestSpan = std::numeric_limits<int>::max();
    bool bestNear = false;
    const QList<Candidate> candidates = m_byFile.value(file);
    for (const Candidate &c : candidates) {
        int span = 0;
        bool hit = false;
        int context = c.instance;
        switch (c.kind) {
        case Kind::LaunchFile: {
            const LaunchFileInstance &lf = launch.instances[c.ref];
            hit = coversLine(lf.evidence, file, line, &span);
            if (hit && lf.file != file) {
                context = m_instanceOwner[c.ref]; // an include line: the includer's
            } else if (!hit && lf.file == file && line > 0) {
                // Any other line of a launch file belongs to the file, below all its items.
                hit = true;
                span = std::numeric_limits<int>::max() - 1;
            }
            break;
        }
        case Kind::Node:
            hit = coversLine(launch.nodes[c.ref].evidence, file, line, &span);
            break;
        case Kind::Unresolved: {
            const LaunchFileInstance &lf = launch.instances[c.instance];
            hit = coversLine(lf.unresolved[c.ref].evidence, file, line, &span) &&
                  placement(lf.unresolved[c.ref], lf, launch) == Placement::Row;
            break;
        }
        case Kind::Namespace:
        case Kind::Parameters: // not laid out: the model makes them
        case Kind::Parameter:
        case Kind::None:
            break;
        }
        if (!hit)
            continue;
        const bool isNear = nearInstance >= 0 && context == nearInstance;
        if (span < bestSpan || (span == bestSpan && isNear && !bestNear)) {
            best = &c;
            bestSpan = span;
            bestNear = isNear;
        }
    }
    if (!best)
        return -1;
    switch (best->kind) {
    case Kind::LaunchFile:
        return launchFileItem(launch.instances[best->ref].id);
    case Kind::Node:
        return nodeItem(launch.nodes[best->ref].id);
    default:
        ensureChildren(launchFileItem(launch.instances[best->instance].id));
        return m_unresolvedItems.value((qint64(best->instance) << 32) | best->ref, -1);
    }
}

} // namespace rosarch
