#include "widgets/atomicnodemodel.h"
#include "core/visibletext.h"
#include "document/document.h"
#include "jobs/stallprobe.h"
#include "widgets/atomicnodetext.h"
#include "widgets/evidencelines.h"
#include "widgets/icons.h"
#include "widgets/treeindexid.h"

#include <QFont>
#include <QGuiApplication>
#include <QPalette>

#include <algorithm>
#include <limits>

namespace rosarch {

namespace {

// A row's internal id: its kind as the tag, and above it where its parent is: for a node row
// the row of its package, for a port, "Parameters" or parameter row its node's index in the
// list. A package row has no parent to name.
using RowId = TreeIndexId<AtomicNodeModel::ItemKind, 3>;
static_assert(RowId::holds(AtomicNodeModel::ItemKind::Parameter));

} // namespace

AtomicNodeModel::AtomicNodeModel(Document *document, QObject *parent)
    : QAbstractItemModel(parent), m_document(document)
{
    connect(document, &Document::aboutToChange, this, [this](const DocumentChange &change) {
        if (change.has(DocumentChange::Model))
            beginResetModel();
    });
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        if (change.has(DocumentChange::Model)) {
            const StallScope scope("AtomicNodeModel reset");
            m_previewNodeId.clear();
            rebuild();
            endResetModel();
        } else if (change.parts & (DocumentChange::Corrections | DocumentChange::Decisions |
                                   DocumentChange::Launch | DocumentChange::Accepted)) {
            if (m_document->isAcceptedPending())
                return; // DocumentChange::Accepted follows
            onCorrectionsChanged();
        } else if (change.has(DocumentChange::Node)) {
            bool differs = false; // a correction may have shown it already
            if (const AtomicNode *n = m_document->atomicNodes().node(change.id))
                for (AtomicNode &here : m_nodes.nodes)
                    if (here.id == change.id && here.description != n->description) {
                        here.description = n->description;
                        differs = true;
                    }
            if (differs)
                onNodeChanged(change.id);
        }
    });
    rebuild();
}

// The classes as corrected, with what a correction removed put back where it was (shown
// struck out): a person sees what they removed, where it was, and can restore it there.
AtomicNodeList AtomicNodeModel::merged()
{
    const AtomicNodeList &recovered = m_document->atomicNodes();
    m_removed.clear();
    m_index = CorrectionIndex(*m_document);
    if (m_document->session()->corrections().isEmpty() &&
        m_document->session()->decisions().isEmpty())
        return recovered;
    const AtomicNodeList &corrected = m_document->accepted().nodes;
    AtomicNodeList out = recovered;
    out.nodes.clear();
    for (const AtomicNode &was : recovered.nodes) {
        const AtomicNode *now = corrected.node(was.id);
        if (!now) {
            m_removed.insert(was.id);
            out.nodes.append(was);
            continue;
        }
        AtomicNode n = *now;
        n.ports.clear();
        for (const Port &p : was.ports) {
            const auto it = std::find_if(now->ports.cbegin(), now->ports.cend(),
                                         [&](const Port &q) { return q.id == p.id; });
            if (it == now->ports.cend())
                m_removed.insert(was.id + u'/' + p.id);
            n.ports.append(it == now->ports.cend() ? p : *it);
        }
        for (const Port &p : now->ports) // added by a correction
            if (std::none_of(was.ports.cbegin(), was.ports.cend(),
                             [&](const Port &q) { return q.id == p.id; }))
                n.ports.append(p);
        n.description = was.description; // the description a person edited last
        out.nodes.append(n);
    }
    return out;
}

void AtomicNodeModel::onCorrectionsChanged()
{
    const QSet<QString> removedBefore = m_removed;
    AtomicNodeList next = merged();
    bool sameShape = next.nodes.size() == m_nodes.nodes.size();
    for (int i = 0; sameShape && i < next.nodes.size(); ++i)
        sameShape = next.nodes[i].ports.size() == m_nodes.nodes[i].ports.size() &&
                    next.nodes[i].parameters.size() == m_nodes.nodes[i].parameters.size();
    if (!sameShape) {
        // an added port appeared or went: the rows change; the panel finds its current row
        // again by stable key (FilteredTreePanel)
        setProperty("rosarch.keepsCurrent", true);
        beginResetModel();
        m_nodes = std::move(next);
        rebuild(false);
        endResetModel();
        setProperty("rosarch.keepsCurrent", false);
        return;
    }
    const AtomicNodeList before = std::exchange(m_nodes, std::move(next));
    QHash<QString, const AtomicNode *> old;
    for (const AtomicNode &n : before.nodes)
        old.insert(n.id, &n);
    // only the rows whose class or ports read differently now (a large workspace has many)
    for (int p = 0; p < m_packages.size(); ++p) {
        const QModelIndex package = index(p, 0);
        for (int r = 0; r < rowCount(package); ++r) {
            const QModelIndex node = index(r, 0, package);
            const AtomicNode *now = this->node(node);
            const AtomicNode *was = now ? old.value(now->id) : nullptr;
            const auto removedHere = [&](const QSet<QString> &removed) {
                QStringList ids;
                for (const QString &id : removed)
                    if (now && (id == now->id || id.startsWith(now->id + u'/')))
                        ids << id;
                ids.sort();
                return ids;
            };
            const bool removedSame = removedHere(removedBefore) == removedHere(m_removed);
            if (now && was && *now == *was && removedSame)
                continue;
            const bool portsSame = now && was && now->ports == was->ports && removedSame;
            Q_EMIT dataChanged(node, node.siblingAtColumn(ColumnCount - 1));
            if (const int ports = rowCount(node); ports > 0 && !portsSame)
                Q_EMIT dataChanged(index(0, 0, node), index(ports - 1, ColumnCount - 1, node));
        }
    }
}

bool AtomicNodeModel::isRemoved(const QModelIndex &index) const
{
    if (const Port *p = port(index))
        return m_removed.contains(node(index)->id + u'/' + p->id) ||
               m_removed.contains(node(index)->id);
    const AtomicNode *n = node(index);
    return n && m_removed.contains(n->id);
}

QString AtomicNodeModel::elementId(const QModelIndex &index) const
{
    if (const ItemKind k = RowId::of(index).tag();
        k == ItemKind::Parameters || k == ItemKind::Parameter) // not elements a correction names
        return {};
    if (const Port *p = port(index))
        return node(index)->id + u'/' + p->id;
    if (const AtomicNode *n = node(index))
        return n->id;
    return {};
}

QString AtomicNodeModel::stableKey(const QModelIndex &index) const
{
    if (kind(index) == ItemKind::Package && !index.parent().isValid())
        return StableKeys::packageKey(m_packages.value(index.row()).name);
    const QString id = elementId(index);
    if (id.isEmpty())
        return {};
    const QString key =
        m_document->session()->keysReady() ? m_document->session()->keyOf(id) : QString();
    return key.isEmpty() ? QStringLiteral("id:") + id : key;
}

QModelIndex AtomicNodeModel::indexOfStableKey(const QString &key) const
{
    if (StableKeys::family(key) == QLatin1String("package"))
        return packageIndex(key.section(u':', 1));
    QString id;
    if (key.startsWith(QLatin1String("id:")))
        id = key.mid(3);
    else if (m_document->session()->keysReady())
        id = m_document->session()->recoveredKeys().idOf(key);
    if (id.isEmpty())
        return {};
    return id.contains(u'/') ? portIndex(id.section(u'/', 0, 0), id.section(u'/', 1))
                             : nodeIndex(id);
}

void AtomicNodeModel::rebuild(bool merge)
{
    if (merge)
        m_nodes = merged();
    const AtomicNodeList &list = m_nodes;
    m_packages.clear();
    m_nodeLocations.clear();
    // Linear in the system's size: a package's row is found by name in a hash.
    QSet<QString> known;
    for (int i = 0; i < list.packages.size(); ++i) {
        m_packages.append({list.packages[i].name, i, {}});
        known.insert(list.packages[i].name);
    }
    for (const AtomicNode &n : list.nodes)
        if (!known.contains(n.packageName)) {
            known.insert(n.packageName);
            m_packages.append({n.packageName, -1, {}});
        }
    std::stable_sort(m_packages.begin(), m_packages.end(),
                     [](const PackageRow &a, const PackageRow &b) { return a.name < b.name; });

    QHash<QString, int> rowOf; // the first row of a name, as the scan over rows found it
    for (int p = int(m_packages.size()) - 1; p >= 0; --p)
        rowOf.insert(m_packages[p].name, p);
    m_nodeLocations.resize(list.nodes.size());
    for (int i = 0; i < list.nodes.size(); ++i) {
        const int p = rowOf.value(list.nodes[i].packageName, -1);
        if (p < 0)
            continue;
        m_nodeLocations[i] = {p, int(m_packages[p].nodes.size())};
        m_packages[p].nodes.append(i);
    }
}

void AtomicNodeModel::onNodeChanged(const QString &nodeId)
{
    const QModelIndex first = nodeIndex(nodeId, 0);
    if (first.isValid())
        Q_EMIT dataChanged(first, first.siblingAtColumn(ColumnCount - 1));
}

const RosPackage *AtomicNodeModel::package(const PackageRow &row) const
{
    return row.package >= 0 ? &m_nodes.packages.at(row.package) : nullptr;
}

QModelIndex AtomicNodeModel::makeIndex(int row, int column, ItemKind kind, qsizetype parent) const
{
    // Only where quintptr has 32 bits could a workspace outgrow the payload.
    return RowId::fits(parent) ? createIndex(row, column, RowId(kind, parent).internalId())
                               : QModelIndex();
}

QModelIndex AtomicNodeModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount || row >= rowCount(parent))
        return {};
    if (!parent.isValid())
        return makeIndex(row, column, ItemKind::Package);
    switch (RowId::of(parent).tag()) {
    case ItemKind::Package:
        return makeIndex(row, column, ItemKind::Node, parent.row());
    case ItemKind::Node: {
        const AtomicNode *node = this->node(parent);
        const bool afterPorts = node && row == node->ports.size();
        return makeIndex(row, column, afterPorts ? ItemKind::Parameters : ItemKind::Port,
                         nodeListIndex(parent));
    }
    case ItemKind::Parameters:
        return makeIndex(row, column, ItemKind::Parameter, RowId::of(parent).payload());
    default:
        return {};
    }
}

QModelIndex AtomicNodeModel::parent(const QModelIndex &child) const
{
    if (!child.isValid())
        return {};
    const RowId id = RowId::of(child);
    switch (id.tag()) {
    case ItemKind::Node:
        return makeIndex(int(id.payload()), 0, ItemKind::Package);
    case ItemKind::Port:
    case ItemKind::Parameters: {
        const NodeLocation loc = m_nodeLocations.value(int(id.payload()));
        return makeIndex(loc.row, 0, ItemKind::Node, loc.packageRow);
    }
    case ItemKind::Parameter: {
        const AtomicNode *node = this->node(child);
        return node ? makeIndex(int(node->ports.size()), 0, ItemKind::Parameters, id.payload())
                    : QModelIndex();
    }
    default:
        return {};
    }
}

int AtomicNodeModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return int(m_packages.size());
    if (parent.column() != 0)
        return 0;
    switch (RowId::of(parent).tag()) {
    case ItemKind::Package:
        return int(m_packages.value(parent.row()).nodes.size());
    case ItemKind::Node: {
        const AtomicNode *n = node(parent);
        return n ? int(n->ports.size()) + (n->parameters.isEmpty() ? 0 : 1) : 0;
    }
    case ItemKind::Parameters: {
        const AtomicNode *n = node(parent);
        return n ? int(n->parameters.size()) : 0;
    }
    default:
        return 0;
    }
}

int AtomicNodeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

int AtomicNodeModel::nodeListIndex(const QModelIndex &index) const
{
    if (!index.isValid())
        return -1;
    const RowId id = RowId::of(index);
    switch (id.tag()) {
    case ItemKind::Port:
    case ItemKind::Parameters:
    case ItemKind::Parameter:
        return int(id.payload());
    case ItemKind::Node: {
        const auto packageRow = int(id.payload());
        if (packageRow >= m_packages.size())
            return -1;
        return m_packages[packageRow].nodes.value(index.row(), -1);
    }
    default:
        return -1;
    }
}

AtomicNodeModel::ItemKind AtomicNodeModel::kind(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return ItemKind::None;
    const ItemKind k = RowId::of(index).tag();
    return k <= ItemKind::Parameter ? k : ItemKind::None;
}

const AtomicNode *AtomicNodeModel::node(const QModelIndex &index) const
{
    const int i = nodeListIndex(index);
    const QList<AtomicNode> &nodes = m_nodes.nodes;
    return i >= 0 && i < nodes.size() ? &nodes[i] : nullptr;
}

const Port *AtomicNodeModel::port(const QModelIndex &index) const
{
    if (kind(index) != ItemKind::Port)
        return nullptr;
    const AtomicNode *n = node(index);
    return n && index.row() < n->ports.size() ? &n->ports[index.row()] : nullptr;
}

const ParameterDeclaration *AtomicNodeModel::parameter(const QModelIndex &index) const
{
    if (kind(index) != ItemKind::Parameter)
        return nullptr;
    const AtomicNode *n = node(index);
    return n && index.row() < n->parameters.size() ? &n->parameters[index.row()] : nullptr;
}

Evidence AtomicNodeModel::evidence(const QModelIndex &index) const
{
    switch (kind(index)) {
    case ItemKind::Package:
        if (const RosPackage *p = package(m_packages.value(index.row())))
            return p->evidence;
        return {};
    case ItemKind::Node:
        return node(index) ? node(index)->evidence : Evidence();
    case ItemKind::Port:
        return port(index) ? port(index)->evidence : Evidence();
    case ItemKind::Parameter:
        return parameter(index) ? parameter(index)->evidence : Evidence();
    case ItemKind::Parameters:
    case ItemKind::None:
        break;
    }
    return {};
}

QModelIndex AtomicNodeModel::packageIndex(const QString &name, int column) const
{
    for (int p = 0; p < m_packages.size(); ++p)
        if (m_packages[p].name == name)
            return index(p, column);
    return {};
}

QModelIndex AtomicNodeModel::nodeIndex(const QString &nodeId, int column) const
{
    const QList<AtomicNode> &nodes = m_nodes.nodes;
    for (int i = 0; i < nodes.size() && i < m_nodeLocations.size(); ++i) {
        if (nodes[i].id == nodeId) {
            const NodeLocation loc = m_nodeLocations[i];
            return makeIndex(loc.row, column, ItemKind::Node, loc.packageRow);
        }
    }
    return {};
}

QModelIndex AtomicNodeModel::portIndex(const QString &nodeId, const QString &portId,
                                       int column) const
{
    const QModelIndex parentIndex = nodeIndex(nodeId);
    const AtomicNode *n = node(parentIndex);
    if (!n)
        return {};
    for (int r = 0; r < n->ports.size(); ++r)
        if (n->ports[r].id == portId)
            return index(r, column, parentIndex);
    return {};
}

QModelIndex AtomicNodeModel::parametersIndex(const QString &nodeId, int column) const
{
    const QModelIndex parentIndex = nodeIndex(nodeId);
    const AtomicNode *n = node(parentIndex);
    if (!n || n->parameters.isEmpty())
        return {};
    return index(int(n->ports.size()), column, parentIndex);
}

QModelIndex AtomicNodeModel::parameterIndex(const QString &nodeId, const QString &name,
                                            int column) const
{
    const QModelIndex group = parametersIndex(nodeId);
    const AtomicNode *n = node(group);
    if (!n)
        return {};
    for (int r = 0; r < n->parameters.size(); ++r)
        if (n->parameters[r].name == name)
            return index(r, column, group);
    return {};
}

QModelIndex AtomicNodeModel::indexAt(const QString &file, int line) const
{
    QModelIndex best;
    int bestSpan = std::numeric_limits<int>::max();
    const QList<AtomicNode> &nodes = m_nodes.nodes;
    for (const AtomicNode &n : nodes) {
        int span = 0;
        // Strictly smaller wins, so on equal spans a node's port (checked first) stays.
        for (const Port &p : n.ports) {
            if (coversLine(p.evidence, file, line, &span) && span < bestSpan) {
                bestSpan = span;
                best = portIndex(n.id, p.id);
            }
        }
        if (coversLine(n.evidence, file, line, &span) && span < bestSpan) {
            bestSpan = span;
            best = nodeIndex(n.id);
        }
    }
    return best;
}

QVariant AtomicNodeModel::data(const QModelIndex &index, int role) const
{
    // Names and file names come from the workspace: a control character in one is shown as an
    // escape, and a newline never makes a row two lines.
    QVariant value = rawData(index, role);
    if (role == Qt::DisplayRole && value.typeId() == QMetaType::QString)
        return visibleText(value.toString());
    return value;
}

QVariant AtomicNodeModel::rawData(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.model() != this)
        return {};
    switch (kind(index)) {
    case ItemKind::Package:
        if (index.row() < m_packages.size())
            return packageData(m_packages[index.row()], index.column(), role);
        return {};
    case ItemKind::Node:
        if (const AtomicNode *n = node(index))
            return nodeData(*n, index.column(), role);
        return {};
    case ItemKind::Port:
        if (const Port *p = port(index))
            return portData(*node(index), *p, index.column(), role);
        return {};
    case ItemKind::Parameters:
        if (const AtomicNode *n = node(index))
            return parametersData(*n, index.column(), role);
        return {};
    case ItemKind::Parameter:
        if (const ParameterDeclaration *p = parameter(index))
            return parameterData(*node(index), *p, index.column(), role);
        return {};
    case ItemKind::None:
        break;
    }
    return {};
}

bool AtomicNodeModel::setData(const QModelIndex &index, const QVariant &value, int role)
{
    if (role != Qt::EditRole || kind(index) != ItemKind::Node ||
        index.column() != DescriptionColumn)
        return false;
    const AtomicNode *n = node(index);
    if (!n)
        return false;
    // The Document pushes an undoable command and tells us through changed (DocumentChange::Node).
    m_document->session()->setNodeDescription(n->id, value.toString());
    return true;
}

Qt::ItemFlags AtomicNodeModel::flags(const QModelIndex &index) const
{
    if (!index.isValid())
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (kind(index) == ItemKind::Node && index.column() == DescriptionColumn)
        f |= Qt::ItemIsEditable;
    if (kind(index) == ItemKind::Port || kind(index) == ItemKind::Parameter)
        f |= Qt::ItemNeverHasChildren;
    return f;
}

QVariant AtomicNodeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Name");
    case TypeColumn:
        return tr("Type");
    case DetailsColumn:
        return tr("Details");
    case DescriptionColumn:
        return tr("Description");
    default:
        return {};
    }
}

} // namespace rosarch
