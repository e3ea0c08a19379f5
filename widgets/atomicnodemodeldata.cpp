// What the atomic node tree shows in each row and column: packages, nodes, ports and declared
// parameters, with the marks of corrections (tint, strike-out, review tick) and a suggested
// description previewed.
#include "compose/itemports.h"
#include "document/document.h"
#include "document/nodedescription.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodetext.h"
#include "widgets/icons.h"

#include <QFont>
#include <QGuiApplication>
#include <QPalette>

namespace rosarch {

QVariant AtomicNodeModel::marksData(const QString &id, const Marks &marks, int column,
                                    int role) const
{
    const bool removed = m_removed.contains(id) || m_removed.contains(id.section(u'/', 0, 0));
    switch (role) {
    case Qt::ForegroundRole:
        if (removed)
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        if (marks.provenance != Provenance::Recovered)
            return QGuiApplication::palette().brush(QPalette::Link);
        return {};
    case ProvenanceRole:
        return removed ? QStringLiteral("removed") : provenanceName(marks.provenance);
    case ReviewedRole:
        return marks.reviewed;
    case Qt::DisplayRole:
        return column == NameColumn && marks.reviewed && !removed ? QStringLiteral(" \u2713")
                                                                  : QString();
    case Qt::ToolTipRole: {
        const QString summary = m_index.summary(id);
        return summary.isEmpty()
                   ? QString()
                   : QStringLiteral("<hr/>") +
                         summary.toHtmlEscaped().replace(u'\n', QStringLiteral("<br/>"));
    }
    default:
        return {};
    }
}

QVariant AtomicNodeModel::packageData(const PackageRow &row, int column, int role) const
{
    const RosPackage *pkg = package(row);
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case NameColumn:
            return row.name.isEmpty() ? tr("(outside any package)") : row.name;
        case TypeColumn:
            return pkg ? pkg->buildType : QString();
        case DetailsColumn: {
            QString details =
                row.nodes.size() == 1 ? tr("1 node") : tr("%1 nodes").arg(row.nodes.size());
            if (pkg && !pkg->path.isEmpty())
                details += QStringLiteral(" · ") + pkg->path;
            return details;
        }
        default:
            return {};
        }
    case Qt::DecorationRole:
        return column == NameColumn ? Icons::package() : QVariant();
    case Qt::ForegroundRole:
        // A package without nodes (interfaces, bringup) is context, not content.
        if (row.nodes.isEmpty())
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case Qt::ToolTipRole:
        return AtomicNodeText::packageToolTip(row.name, pkg, int(row.nodes.size()));
    case KindRole:
        return int(ItemKind::Package);
    default:
        return {};
    }
}

void AtomicNodeModel::setDescriptionPreview(const QString &nodeId, const QString &description)
{
    if (nodeId == m_previewNodeId && description == m_previewDescription)
        return;
    const QString previous = m_previewNodeId;
    m_previewNodeId = nodeId;
    m_previewDescription = description;
    for (const QString &id : {previous, nodeId}) {
        const QModelIndex index = nodeIndex(id, DescriptionColumn);
        if (index.isValid())
            Q_EMIT dataChanged(index, index, {Qt::DisplayRole, Qt::FontRole});
    }
}

QVariant AtomicNodeModel::nodeData(const AtomicNode &node, int column, int role) const
{
    switch (role) {
    case Qt::DisplayRole:
    case Qt::EditRole:
        switch (column) {
        case NameColumn:
            return role == Qt::DisplayRole
                       ? node.className + marksData(node.id, node.marks, column, role).toString()
                       : node.className;
        case TypeColumn:
            if (node.procedural)
                return tr("procedural node");
            if (node.isPlugin())
                return tr("plugin: %1").arg(node.pluginInterface);
            return node.baseClasses.join(QStringLiteral(", "));
        case DetailsColumn:
            return AtomicNodeText::nodeDetails(node);
        case DescriptionColumn:
            if (role == Qt::DisplayRole && node.id == m_previewNodeId)
                return tr("%1 (suggested)").arg(m_previewDescription);
            return node.description;
        default:
            return {};
        }
    case Qt::DecorationRole:
        return column == NameColumn ? Icons::node() : QVariant();
    case Qt::FontRole: {
        QFont f;
        f.setItalic(column == DescriptionColumn && node.id == m_previewNodeId);
        f.setStrikeOut(m_removed.contains(node.id));
        return f.italic() || f.strikeOut() ? QVariant(f) : QVariant();
    }
    case Qt::ToolTipRole: {
        NodeDescription description = NodeDescription::of(*m_document, node.id);
        const bool fromCode =
            node.description.isEmpty() && description.source == NodeDescription::Source::Code;
        if (description.text != node.description && !fromCode) // a preview: as shown
            description = {node.description, node.description.isEmpty()
                                                 ? NodeDescription::Source::None
                                                 : NodeDescription::Source::Code};
        return AtomicNodeText::nodeToolTip(node, description, loadedPlugins(node.id)) +
               marksData(node.id, node.marks, column, role).toString();
    }
    case Qt::ForegroundRole:
    case ProvenanceRole:
    case ReviewedRole:
        return marksData(node.id, node.marks, column, role);
    case KindRole:
        return int(ItemKind::Node);
    case NodeIdRole:
        return node.id;
    default:
        return {};
    }
}

QList<const AtomicNode *> AtomicNodeModel::loadedPlugins(const QString &classId) const
{
    QHash<QString, const AtomicNode *> pluginClasses;
    for (const AtomicNode &n : m_nodes.nodes)
        if (n.isPlugin())
            pluginClasses.insert(n.qualifiedName, &n);
    QList<const AtomicNode *> out;
    if (pluginClasses.isEmpty())
        return out;
    for (const NodeInstance &instance : m_document->launchDependencies().nodes) {
        if (instance.classId != classId)
            continue;
        for (const ParameterSetting &plugin : instance.plugins)
            if (const AtomicNode *cls = pluginClass(plugin.value, pluginClasses);
                cls && !out.contains(cls))
                out.append(cls);
    }
    std::sort(out.begin(), out.end(), [](const AtomicNode *a, const AtomicNode *b) {
        return std::tie(a->className, a->qualifiedName) < std::tie(b->className, b->qualifiedName);
    });
    return out;
}

QVariant AtomicNodeModel::portData(const AtomicNode &node, const Port &port, int column,
                                   int role) const
{
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case NameColumn:
            return (port.name.isEmpty() ? port.nameExpression : port.name) +
                   marksData(node.id + u'/' + port.id, port.marks, column, role).toString();
        case TypeColumn:
            return port.type;
        case DetailsColumn:
            return AtomicNodeText::portDetails(port);
        default:
            return {};
        }
    case Qt::DecorationRole:
        return column == NameColumn ? Icons::port(port.kind) : QVariant();
    case Qt::FontRole: {
        QFont f;
        f.setItalic(column == NameColumn && !port.isResolved());
        f.setStrikeOut(m_removed.contains(node.id + u'/' + port.id) || m_removed.contains(node.id));
        return f.italic() || f.strikeOut() ? QVariant(f) : QVariant();
    }
    case Qt::ToolTipRole:
        return AtomicNodeText::portToolTip(node, port) +
               marksData(node.id + u'/' + port.id, port.marks, column, role).toString();
    case Qt::ForegroundRole:
    case ProvenanceRole:
    case ReviewedRole:
        return marksData(node.id + u'/' + port.id, port.marks, column, role);
    case KindRole:
        return int(ItemKind::Port);
    case NodeIdRole:
        return node.id;
    case PortIdRole:
        return port.id;
    default:
        return {};
    }
}

QVariant AtomicNodeModel::parametersData(const AtomicNode &node, int column, int role) const
{
    switch (role) {
    case Qt::DisplayRole:
        if (column == NameColumn)
            return tr("Parameters");
        if (column == DetailsColumn)
            return AtomicNodeText::parametersDetails(node);
        return {};
    case Qt::ToolTipRole:
        return AtomicNodeText::parametersToolTip(node);
    case Qt::ForegroundRole:
        if (m_removed.contains(node.id))
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case KindRole:
        return int(ItemKind::Parameters);
    case NodeIdRole:
        return node.id;
    default:
        return {};
    }
}

QVariant AtomicNodeModel::parameterData(const AtomicNode &node,
                                        const ParameterDeclaration &parameter, int column,
                                        int role) const
{
    switch (role) {
    case Qt::DisplayRole:
        switch (column) {
        case NameColumn:
            return parameter.name;
        case TypeColumn:
            return parameter.type;
        case DetailsColumn:
            return AtomicNodeText::parameterDetails(parameter);
        case DescriptionColumn:
            return parameter.description;
        default:
            return {};
        }
    case Qt::FontRole: {
        // a name with parts the code decides at run time, as an unresolved port's
        QFont f;
        f.setItalic(column == NameColumn && parameterNameIsPattern(parameter.name));
        f.setStrikeOut(m_removed.contains(node.id));
        return f.italic() || f.strikeOut() ? QVariant(f) : QVariant();
    }
    case Qt::ToolTipRole:
        return AtomicNodeText::parameterToolTip(node, parameter);
    case Qt::ForegroundRole:
        if (m_removed.contains(node.id))
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case KindRole:
        return int(ItemKind::Parameter);
    case NodeIdRole:
        return node.id;
    case ParameterNameRole:
        return parameter.name;
    default:
        return {};
    }
}

} // namespace rosarch
