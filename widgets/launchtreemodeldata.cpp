// What the launch tree shows in each row and column: launch files, namespace scopes, node
// instances (as corrected: tinted, struck out, ticked), unresolved actions and parameters.
#include "core/visibletext.h"
#include "document/document.h"
#include "widgets/icons.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreetext.h"

#include <QFont>
#include <QGuiApplication>
#include <QIcon>
#include <QPalette>

#include <algorithm>

namespace rosarch {

QVariant LaunchTreeModel::data(const QModelIndex &index, int role) const
{
    // Names and file names come from the workspace: a control character in one is shown as an
    // escape, and a newline never makes a row two lines.
    QVariant value = rawData(index, role);
    if (role == Qt::DisplayRole && value.typeId() == QMetaType::QString)
        return visibleText(value.toString());
    return value;
}

QVariant LaunchTreeModel::rawData(const QModelIndex &index, int role) const
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
