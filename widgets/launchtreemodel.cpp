#include "widgets/launchtreemodel.h"
#include "document/document.h"
#include "jobs/stallprobe.h"
#include "widgets/icons.h"
#include "widgets/launchtreetext.h"

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
        else if (change.parts & (DocumentChange::Corrections | DocumentChange::Decisions |
                                 DocumentChange::Accepted) &&
                 !m_document->isAcceptedPending()) // else DocumentChange::Accepted follows
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
    m_layout = LaunchTreeLayout(&m_launch);
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
    if (m_document->session()->corrections().isEmpty())
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
    // a part was added or its addition undone: the rows change; the panel finds its current
    // row again by stable key (FilteredTreePanel)
    setProperty("rosarch.keepsCurrent", true);
    beginResetModel();
    m_launch = next;
    m_layout = LaunchTreeLayout(&m_launch);
    endResetModel();
    setProperty("rosarch.keepsCurrent", false);
}

bool LaunchTreeModel::isRemoved(const QModelIndex &index) const
{
    const NodeInstance *n = node(index);
    return n && m_removed.contains(n->id);
}

QString LaunchTreeModel::stableKey(const QModelIndex &index) const
{
    QString id;
    if (kind(index) == ItemKind::Node) {
        if (const NodeInstance *n = node(index))
            id = n->id;
    } else if (kind(index) == ItemKind::LaunchFile) {
        if (const LaunchFileInstance *lf = launchFile(index))
            id = lf->id;
    }
    if (id.isEmpty())
        return {};
    const QString key =
        m_document->session()->keysReady() ? m_document->session()->keyOf(id) : QString();
    return key.isEmpty() ? QStringLiteral("id:") + id : key;
}

QModelIndex LaunchTreeModel::indexOfStableKey(const QString &key) const
{
    QString id;
    if (key.startsWith(QLatin1String("id:")))
        id = key.mid(3);
    else if (m_document->session()->keysReady())
        id = m_document->session()->recoveredKeys().idOf(key);
    if (id.isEmpty())
        return {};
    const QModelIndex node = nodeIndex(id);
    return node.isValid() ? node : launchFileIndex(id);
}

QString LaunchTreeModel::correctionSummary(const QString &id) const
{
    return m_index.summary(id);
}

int LaunchTreeModel::itemOf(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return -1;
    const RowId id = RowId::of(index);
    return id.tag() == RowTag::Item && id.payload() < m_layout.items().size() ? int(id.payload())
                                                                              : -1;
}

const NodeInstance *LaunchTreeModel::nodeOfItem(int item) const
{
    const QList<Item> &items = m_layout.items();
    if (item < 0 || item >= items.size() || items[item].kind != ItemKind::Node)
        return nullptr;
    return &m_launch.nodes[items[item].ref];
}

int LaunchTreeModel::parameterCount(int item) const
{
    const NodeInstance *n = nodeOfItem(item);
    if (!n || n->effectiveParameters.isEmpty())
        return 0;
    // Rows the ids cannot name are not shown at all, rather than counted and left invalid.
    const qsizetype count = n->effectiveParameters.size();
    return RowId::fits(item, count - 1) ? int(count) : 0;
}

QModelIndex LaunchTreeModel::makeIndex(int row, int column, RowTag tag, qsizetype item,
                                       qsizetype parameter) const
{
    if (tag == RowTag::Parameter)
        return RowId::fits(item, parameter)
                   ? createIndex(row, column, RowId::split(tag, item, parameter).internalId())
                   : QModelIndex();
    return RowId::fits(item) ? createIndex(row, column, RowId(tag, item).internalId())
                             : QModelIndex();
}

int LaunchTreeModel::parameterRowOf(const QModelIndex &index, int *k) const
{
    *k = -1;
    if (!index.isValid() || index.model() != this)
        return -1;
    const RowId id = RowId::of(index);
    int item = -1;
    if (id.tag() == RowTag::Parameters) {
        item = int(id.payload());
    } else if (id.tag() == RowTag::Parameter) {
        item = int(id.high());
        *k = int(id.low());
    }
    const int count = parameterCount(item);
    if (count == 0 || *k >= count)
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
    return makeIndex(items[item].row, column, RowTag::Item, item);
}

QModelIndex LaunchTreeModel::index(int row, int column, const QModelIndex &parent) const
{
    const QList<Item> &items = m_layout.items();
    if (row < 0 || column < 0 || column >= ColumnCount)
        return {};
    if (!parent.isValid())
        return row < m_layout.roots().size()
                   ? makeIndex(row, column, RowTag::Item, m_layout.roots()[row])
                   : QModelIndex();
    if (parent.column() != 0)
        return {};
    int k = -1;
    if (const int owner = parameterRowOf(parent, &k); owner >= 0) {
        if (k >= 0 || row >= parameterCount(owner))
            return {};
        return makeIndex(row, column, RowTag::Parameter, owner, row);
    }
    const int p = itemOf(parent);
    if (p < 0)
        return {};
    m_layout.ensureChildren(p);
    if (row == items[p].children.size() && parameterCount(p) > 0)
        return makeIndex(row, column, RowTag::Parameters, p);
    if (row >= items[p].children.size())
        return {};
    return makeIndex(row, column, RowTag::Item, items[p].children[row]);
}

QModelIndex LaunchTreeModel::parent(const QModelIndex &child) const
{
    const QList<Item> &items = m_layout.items();
    int k = -1;
    if (const int owner = parameterRowOf(child, &k); owner >= 0)
        return k < 0 ? indexOfItem(owner, 0)
                     : makeIndex(int(items[owner].children.size()), 0, RowTag::Parameters, owner);
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
        return k < 0 ? parameterCount(owner) : 0;
    const int item = itemOf(parent);
    if (item < 0)
        return 0;
    m_layout.ensureChildren(item);
    return int(items[item].children.size()) + (parameterCount(item) > 0 ? 1 : 0);
}

bool LaunchTreeModel::hasChildren(const QModelIndex &parent) const
{
    // A launch file's rows are made when it is opened, not when the view draws its arrow.
    if (const int item = itemOf(parent);
        item >= 0 && m_layout.items()[item].kind == ItemKind::LaunchFile)
        return parent.column() == 0 && m_layout.hasChildren(item);
    return QAbstractItemModel::hasChildren(parent);
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
    return indexOfItem(m_layout.itemAt(file, line, itemOf(near)), 0);
}

} // namespace rosarch
