#include "launchtreemodel.h"
#include "document.h"
#include "icons.h"
#include "launchtreetext.h"
#include "stallprobe.h"

#include <QFont>
#include <QGuiApplication>
#include <QIcon>
#include <QPalette>

#include <algorithm>

namespace rosarch {

LaunchTreeModel::LaunchTreeModel(Document *document, QObject *parent)
    : QAbstractItemModel(parent), m_document(document)
{
    const auto begin = [this] { beginResetModel(); };
    const auto end = [this] {
        const StallScope scope("LaunchTreeModel reset");
        rebuild();
        endResetModel();
    };
    connect(document, &Document::aboutToChange, this, [begin](const DocumentChange &change) {
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch))
            begin();
    });
    connect(document, &Document::changed, this, [this, end](const DocumentChange &change) {
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch))
            end();
        else if (change.parts & (DocumentChange::Corrections | DocumentChange::Decisions))
            onCorrectionsChanged();
    });
    // Class names in tooltips come from the atomic nodes; a description edit changes nothing here.
    rebuild();
}

void LaunchTreeModel::rebuild()
{
    {
        const StallScope scope("LaunchTreeModel merged");
        m_launch = merged();
    }
    const StallScope scope("LaunchTreeModel layout");
    m_layout = LaunchTreeLayout(m_launch);
}

// The launch dependencies as corrected, with the node instances a correction removed put back
// where they were (struck out): the tree keeps the shape of the launch files, so a person sees
// what they removed in its place and can restore it from there.
LaunchDependencies LaunchTreeModel::merged()
{
    const LaunchDependencies &recovered = m_document->launchDependencies();
    m_removed.clear();
    {
        const StallScope scope("LaunchTreeModel CorrectionIndex");
        m_index = CorrectionIndex(*m_document);
    }
    if (m_document->corrections().isEmpty())
        return recovered;
    const LaunchDependencies &corrected = m_document->accepted().launch;
    LaunchDependencies out = corrected;
    out.nodes.clear();
    for (const NodeInstance &was : recovered.nodes) {
        const auto it = std::find_if(corrected.nodes.cbegin(), corrected.nodes.cend(),
                                     [&](const NodeInstance &n) { return n.id == was.id; });
        if (it == corrected.nodes.cend())
            m_removed.insert(was.id);
        out.nodes.append(it == corrected.nodes.cend() ? was : *it);
    }
    for (const NodeInstance &n : corrected.nodes) // added by a correction
        if (std::none_of(recovered.nodes.cbegin(), recovered.nodes.cend(),
                         [&](const NodeInstance &r) { return r.id == n.id; }))
            out.nodes.append(n);
    for (LaunchFileInstance &lf : out.instances) {
        const auto was = std::find_if(recovered.instances.cbegin(), recovered.instances.cend(),
                                      [&](const LaunchFileInstance &r) { return r.id == lf.id; });
        if (was == recovered.instances.cend())
            continue;
        QStringList nodes = was->nodes;
        for (const QString &id : std::as_const(lf.nodes))
            if (!nodes.contains(id))
                nodes.append(id);
        lf.nodes = nodes;
    }
    return out;
}

void LaunchTreeModel::onCorrectionsChanged()
{
    const LaunchDependencies next = merged();
    if (next.nodes.size() == m_launch.nodes.size()) {
        m_launch = next;
        for (int i = 0; i < m_layout.items().size(); ++i)
            if (m_layout.items()[i].kind == ItemKind::Node ||
                m_layout.items()[i].kind == ItemKind::LaunchFile)
                Q_EMIT dataChanged(indexOfItem(i, 0), indexOfItem(i, ColumnCount - 1));
        return;
    }
    // a part was added or its addition undone: the rows change, the current row is kept by place
    setProperty("rosarch.keepsCurrent", true);
    beginResetModel();
    m_launch = next;
    m_layout = LaunchTreeLayout(m_launch);
    endResetModel();
    setProperty("rosarch.keepsCurrent", false);
}

bool LaunchTreeModel::isRemoved(const QModelIndex &index) const
{
    const NodeInstance *n = node(index);
    return n && m_removed.contains(n->id);
}

QString LaunchTreeModel::correctionSummary(const QString &id) const
{
    return m_index.summary(id);
}

int LaunchTreeModel::itemOf(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return -1;
    const quintptr id = index.internalId();
    return id < quintptr(m_layout.items().size()) ? int(id) : -1;
}

const NodeInstance *LaunchTreeModel::nodeOfItem(int item) const
{
    const QList<Item> &items = m_layout.items();
    if (item < 0 || item >= items.size() || items[item].kind != ItemKind::Node)
        return nullptr;
    return &m_launch.nodes[items[item].ref];
}

int LaunchTreeModel::parameterRowOf(const QModelIndex &index, int *k) const
{
    if (!index.isValid() || index.model() != this)
        return -1;
    const quintptr id = index.internalId();
    int item = -1;
    *k = -1;
    if (id & kParametersTag) {
        item = int(id & ~kParametersTag);
    } else if (id & kParameterTag) {
        item = int((id & ~kParameterTag) >> kParameterBits);
        *k = int(id & ((quintptr(1) << kParameterBits) - 1));
    }
    const NodeInstance *n = nodeOfItem(item);
    if (!n || n->effectiveParameters.isEmpty() || *k >= n->effectiveParameters.size())
        return -1;
    return item;
}

const ParameterSetting *LaunchTreeModel::parameter(const QModelIndex &index) const
{
    int k = -1;
    const int item = parameterRowOf(index, &k);
    return item < 0 || k < 0 ? nullptr : &nodeOfItem(item)->effectiveParameters[k];
}

QModelIndex LaunchTreeModel::indexOfItem(int item, int column) const
{
    const QList<Item> &items = m_layout.items();
    if (item < 0 || item >= m_layout.items().size())
        return {};
    return createIndex(items[item].row, column, quintptr(item));
}

QModelIndex LaunchTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    const QList<Item> &items = m_layout.items();
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid())
        return row < m_layout.roots().size()
                   ? createIndex(row, column, quintptr(m_layout.roots()[row]))
                   : QModelIndex();
    if (parent.column() != 0)
        return {};
    int k = -1;
    if (const int owner = parameterRowOf(parent, &k); owner >= 0) {
        const qsizetype count = nodeOfItem(owner)->effectiveParameters.size();
        if (k >= 0 || row >= count || count >= (qsizetype(1) << kParameterBits))
            return {};
        return createIndex(row, column,
                           kParameterTag | (quintptr(owner) << kParameterBits) | quintptr(row));
    }
    const int p = itemOf(parent);
    if (p < 0)
        return {};
    if (row == items[p].children.size() && nodeOfItem(p) &&
        !nodeOfItem(p)->effectiveParameters.isEmpty())
        return createIndex(row, column, kParametersTag | quintptr(p));
    if (row >= items[p].children.size())
        return {};
    return createIndex(row, column, quintptr(items[p].children[row]));
}

QModelIndex LaunchTreeModel::parent(const QModelIndex &child) const
{
    const QList<Item> &items = m_layout.items();
    int k = -1;
    if (const int owner = parameterRowOf(child, &k); owner >= 0)
        return k < 0 ? indexOfItem(owner, 0)
                     : createIndex(int(items[owner].children.size()), 0,
                                   kParametersTag | quintptr(owner));
    const int item = itemOf(child);
    return item < 0 ? QModelIndex() : indexOfItem(items[item].parent, 0);
}

int LaunchTreeModel::rowCount(const QModelIndex &parent) const
{
    const QList<Item> &items = m_layout.items();
    if (!parent.isValid())
        return int(m_layout.roots().size());
    if (parent.column() != 0)
        return 0;
    int k = -1;
    if (const int owner = parameterRowOf(parent, &k); owner >= 0)
        return k < 0 ? int(nodeOfItem(owner)->effectiveParameters.size()) : 0;
    const int item = itemOf(parent);
    if (item < 0)
        return 0;
    const NodeInstance *n = nodeOfItem(item);
    return int(items[item].children.size()) + (n && !n->effectiveParameters.isEmpty() ? 1 : 0);
}

int LaunchTreeModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

LaunchTreeModel::ItemKind LaunchTreeModel::kind(const QModelIndex &index) const
{
    const QList<Item> &items = m_layout.items();
    int k = -1;
    if (parameterRowOf(index, &k) >= 0)
        return k < 0 ? ItemKind::Parameters : ItemKind::Parameter;
    const int item = itemOf(index);
    return item < 0 ? ItemKind::None : items[item].kind;
}

const LaunchFileInstance *LaunchTreeModel::launchFile(const QModelIndex &index) const
{
    const QList<Item> &items = m_layout.items();
    const int item = itemOf(index);
    const QList<LaunchFileInstance> &all = m_launch.instances;
    return item < 0 || items[item].instance >= all.size() ? nullptr : &all[items[item].instance];
}

const NodeInstance *LaunchTreeModel::node(const QModelIndex &index) const
{
    const QList<Item> &items = m_layout.items();
    const int item = itemOf(index);
    if (item < 0 || items[item].kind != ItemKind::Node)
        return nullptr;
    return &m_launch.nodes[items[item].ref];
}

const Unresolved *LaunchTreeModel::unresolved(const QModelIndex &index) const
{
    const QList<Item> &items = m_layout.items();
    const int item = itemOf(index);
    if (item < 0 || items[item].kind != ItemKind::Unresolved)
        return nullptr;
    return &launchFile(index)->unresolved[items[item].ref];
}

Evidence LaunchTreeModel::evidence(const QModelIndex &index) const
{
    switch (kind(index)) {
    case ItemKind::LaunchFile: {
        const LaunchFileInstance *lf = launchFile(index);
        if (lf->evidence.isValid())
            return lf->evidence;
        // A root whose evidence is the file itself: show its top.
        return lf->file.isEmpty() ? Evidence() : Evidence{lf->file, 1, 0, 1, 0};
    }
    case ItemKind::Node:
        return node(index)->evidence;
    case ItemKind::Unresolved:
        return unresolved(index)->evidence;
    case ItemKind::Parameter:
        return parameter(index)->evidence;
    case ItemKind::Parameters:
    case ItemKind::Namespace:
    case ItemKind::None:
        break;
    }
    return {};
}

bool LaunchTreeModel::isActive(const QModelIndex &index) const
{
    const QList<Item> &items = m_layout.items();
    int k = -1;
    if (const int owner = parameterRowOf(index, &k); owner >= 0)
        return items[owner].active;
    const int item = itemOf(index);
    return item < 0 || items[item].active;
}

QModelIndex LaunchTreeModel::launchFileIndex(const QString &instanceId, int column) const
{
    return indexOfItem(m_layout.launchFileItem(instanceId), column);
}

QModelIndex LaunchTreeModel::nodeIndex(const QString &nodeId, int column) const
{
    return indexOfItem(m_layout.nodeItem(nodeId), column);
}

QModelIndex LaunchTreeModel::indexAt(const QString &file, int line, const QModelIndex &near) const
{
    return indexOfItem(m_layout.itemAt(m_launch, file, line, itemOf(near)), 0);
}

QVariant LaunchTreeModel::data(const QModelIndex &index, int role) const
{
    const QList<Item> &items = m_layout.items();
    int k = -1;
    if (parameterRowOf(index, &k) >= 0)
        return parameterData(index, role);
    const int item = itemOf(index);
    if (item < 0)
        return {};
    const Item &it = items[item];
    if (role == Qt::ForegroundRole && !it.active)
        return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
    if (it.kind == ItemKind::Node) {
        const NodeInstance &n = m_launch.nodes[it.ref];
        const bool removed = m_removed.contains(n.id);
        if (role == Qt::ForegroundRole && removed)
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        if (role == Qt::ForegroundRole && n.marks.provenance != Provenance::Recovered)
            return QGuiApplication::palette().brush(QPalette::Link);
        if (role == ProvenanceRole)
            return removed ? QStringLiteral("removed") : provenanceName(n.marks.provenance);
        if (role == ReviewedRole)
            return n.marks.reviewed;
        if (role == Qt::FontRole && removed) {
            QFont f = nodeData(it, index.column(), role).value<QFont>();
            f.setStrikeOut(true);
            return f;
        }
        if (role == Qt::DisplayRole && index.column() == NameColumn && n.marks.reviewed && !removed)
            return nodeData(it, index.column(), role).toString() + QStringLiteral(" \u2713");
        if (role == Qt::ToolTipRole && !m_index.isEmpty()) {
            const QString summary = m_index.summary(n.id);
            if (!summary.isEmpty())
                return nodeData(it, index.column(), role).toString() + QStringLiteral("<hr/>") +
                       summary.toHtmlEscaped().replace(u'\n', QStringLiteral("<br/>"));
        }
    }
    if (role == ActiveRole)
        return it.active;
    if (role == KindRole)
        return int(it.kind);
    if (role == InstanceIdRole && it.kind != ItemKind::Node)
        return m_launch.instances.value(it.instance).id;
    QVariant value;
    switch (it.kind) {
    case ItemKind::LaunchFile:
        value = launchFileData(it, index.column(), role);
        break;
    case ItemKind::Namespace:
        value = namespaceData(it, index.column(), role);
        break;
    case ItemKind::Node:
        value = nodeData(it, index.column(), role);
        break;
    case ItemKind::Unresolved:
        value = unresolvedData(it, index.column(), role);
        break;
    case ItemKind::Parameters:
    case ItemKind::Parameter:
    case ItemKind::None:
        break;
    }
    // Inactive rows are greyed, icons included.
    if (role == Qt::DecorationRole && !it.active && value.canConvert<QIcon>())
        return QIcon(value.value<QIcon>().pixmap(QSize(16, 16), QIcon::Disabled));
    return value;
}

Qt::ItemFlags LaunchTreeModel::flags(const QModelIndex &index) const
{
    const QList<Item> &items = m_layout.items();
    int k = -1;
    if (parameterRowOf(index, &k) >= 0)
        return Qt::ItemIsEnabled | Qt::ItemIsSelectable |
               (k >= 0 ? Qt::ItemNeverHasChildren : Qt::NoItemFlags);
    const int item = itemOf(index);
    if (item < 0)
        return Qt::NoItemFlags;
    Qt::ItemFlags f = Qt::ItemIsEnabled | Qt::ItemIsSelectable;
    if (rowCount(index.siblingAtColumn(0)) == 0 && items[item].kind != ItemKind::LaunchFile &&
        items[item].kind != ItemKind::Namespace)
        f |= Qt::ItemNeverHasChildren;
    return f;
}

QVariant LaunchTreeModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Name");
    case NamespaceColumn:
        return tr("Namespace");
    case ExecutableColumn:
        return tr("Package / executable");
    case ClassColumn:
        return tr("Class");
    case DetailsColumn:
        return tr("Details");
    default:
        return {};
    }
}

QVariant LaunchTreeModel::launchFileData(const Item &item, int column, int role) const
{
    const QList<Item> &items = m_layout.items();
    const LaunchFileInstance &lf = m_launch.instances[item.ref];
    const bool unresolvedInclude = lf.file.isEmpty() && !lf.external;
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case NameColumn:
            if (!lf.type.isEmpty())
                return lf.type;
            return lf.file.isEmpty() ? tr("(unresolved include)") : lf.file.section('/', -1);
        case ExecutableColumn:
            return lf.package;
        case DetailsColumn:
            return LaunchTreeText::launchFileDetails(lf);
        default:
            return {};
        }
    case Qt::DecorationRole:
        if (column == NameColumn) {
            if (lf.external)
                return Icons::externalInclude();
            if (unresolvedInclude)
                return Icons::unresolved();
            return lf.parentId.isEmpty() ? Icons::launchFile() : Icons::include();
        }
        if (column == DetailsColumn && !unresolvedInclude &&
            !LaunchTreeLayout::attributeUnresolved(lf, m_launch).isEmpty())
            return Icons::unresolved();
        return {};
    case Qt::FontRole:
        if (column == NameColumn && (lf.parentId.isEmpty() || lf.external || unresolvedInclude)) {
            QFont f;
            f.setBold(lf.parentId.isEmpty());
            f.setItalic(lf.external || unresolvedInclude);
            return f;
        }
        return {};
    case Qt::ToolTipRole: {
        const int parent = item.parent;
        return LaunchTreeText::launchFileToolTip(
            lf, LaunchTreeLayout::attributeUnresolved(lf, m_launch),
            parent < 0 || items[parent].active);
    }
    default:
        return {};
    }
}

QVariant LaunchTreeModel::namespaceData(const Item &item, int column, int role) const
{
    switch (role) {
    case Qt::DisplayRole:
        if (column == NameColumn)
            return item.nameSpace;
        if (column == DetailsColumn)
            return tr("namespace scope");
        return {};
    case Qt::DecorationRole:
        return column == NameColumn ? Icons::nameSpace() : QVariant();
    case Qt::ToolTipRole:
        return LaunchTreeText::namespaceToolTip(item.nameSpace, m_launch.instances[item.instance],
                                                int(item.children.size()));
    default:
        return {};
    }
}

QVariant LaunchTreeModel::nodeData(const Item &item, int column, int role) const
{
    const QList<Item> &items = m_layout.items();
    const NodeInstance &n = m_launch.nodes[item.ref];
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case NameColumn:
            return n.nodeName.isEmpty() ? n.execName : n.nodeName;
        case NamespaceColumn:
            return n.nameSpace.isEmpty() ? QStringLiteral("/") : n.nameSpace;
        case ExecutableColumn:
            return LaunchTreeText::nodeExecutable(n);
        case ClassColumn:
            if (!n.className.isEmpty())
                return n.className;
            return isWorkspacePackage(n.package) ? tr("(not found)") : tr("(external)");
        case DetailsColumn:
            return LaunchTreeText::nodeDetails(n, item.composableCount);
        default:
            return {};
        }
    case Qt::DecorationRole:
        if (column == NameColumn) {
            if (item.composableCount > 0)
                return Icons::container();
            return n.nodeKind == QLatin1String("composable") ? Icons::composable()
                                                             : Icons::nodeInstance();
        }
        if (column == DetailsColumn && !n.unresolved.isEmpty())
            return Icons::unresolved();
        return {};
    case Qt::FontRole:
        if (column == ClassColumn && n.className.isEmpty()) {
            QFont f;
            f.setItalic(true);
            return f;
        }
        return {};
    case Qt::ToolTipRole: {
        const AtomicNode *cls =
            n.classId.isEmpty() ? nullptr : m_document->atomicNodes().node(n.classId);
        const int parent = item.parent;
        return LaunchTreeText::nodeToolTip(n, cls, isWorkspacePackage(n.package),
                                           parent < 0 || items[parent].active);
    }
    case InstanceIdRole:
        return n.id;
    case ClassIdRole:
        return n.classId;
    default:
        return {};
    }
}

bool LaunchTreeModel::isWorkspacePackage(const QString &package) const
{
    const QList<RosPackage> &packages = m_document->atomicNodes().packages;
    return std::any_of(packages.cbegin(), packages.cend(),
                       [&](const RosPackage &p) { return p.name == package; });
}

QVariant LaunchTreeModel::parameterData(const QModelIndex &index, int role) const
{
    int k = -1;
    const int owner = parameterRowOf(index, &k);
    const NodeInstance *n = nodeOfItem(owner);
    const bool active = m_layout.items()[owner].active;
    switch (role) {
    case Qt::ForegroundRole:
        return active ? QVariant()
                      : QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
    case ActiveRole:
        return active;
    case KindRole:
        return int(k < 0 ? ItemKind::Parameters : ItemKind::Parameter);
    case InstanceIdRole:
        return n->id;
    default:
        break;
    }
    if (k < 0) {
        if (role == Qt::DisplayRole && index.column() == NameColumn)
            return tr("Parameters");
        if (role == Qt::DisplayRole && index.column() == DetailsColumn)
            return tr("%n in effect", nullptr, int(n->effectiveParameters.size()));
        if (role == Qt::ToolTipRole)
            return tr("The parameters this instance runs with, and where each comes from: the "
                      "launch file, a parameter file, or the default in code.");
        return {};
    }
    const ParameterSetting &p = n->effectiveParameters[k];
    if (role == Qt::DisplayRole && index.column() == NameColumn)
        return p.name;
    if (role == Qt::DisplayRole && index.column() == DetailsColumn)
        return LaunchTreeText::parameterDetails(p);
    if (role == Qt::ToolTipRole)
        return LaunchTreeText::parameterToolTip(p);
    return {};
}

QVariant LaunchTreeModel::unresolvedData(const Item &item, int column, int role) const
{
    const Unresolved &u = m_launch.instances[item.instance].unresolved[item.ref];
    switch (role) {
    case Qt::DisplayRole:
        if (column == NameColumn)
            return u.expression.simplified();
        if (column == DetailsColumn)
            return LaunchTreeText::unresolvedDetails(u);
        return {};
    case Qt::DecorationRole:
        return column == NameColumn ? Icons::unresolved() : QVariant();
    case Qt::FontRole:
        if (column == NameColumn) {
            QFont f;
            f.setItalic(true);
            return f;
        }
        return {};
    case Qt::ToolTipRole:
        return LaunchTreeText::unresolvedToolTip(u);
    default:
        return {};
    }
}

} // namespace rosarch
