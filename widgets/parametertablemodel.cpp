#include "widgets/parametertablemodel.h"

#include "core/visibletext.h"

#include <QBrush>
#include <QFileInfo>
#include <QFont>
#include <QPalette>

namespace rosarch {

ParameterTableModel::ParameterTableModel(QObject *parent) : QAbstractTableModel(parent) {}

void ParameterTableModel::setParameters(const QList<InstanceParameter> &parameters)
{
    beginResetModel();
    m_parameters = parameters;
    endResetModel();
}

const InstanceParameter *ParameterTableModel::parameter(const QModelIndex &index) const
{
    if (!index.isValid() || index.row() >= m_parameters.size())
        return nullptr;
    return &m_parameters.at(index.row());
}

int ParameterTableModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_parameters.size());
}

int ParameterTableModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

QString ParameterTableModel::sourceText(const InstanceParameter &p) const
{
    if (p.source == QLatin1String("file"))
        return tr("%1:%2")
            .arg(QFileInfo(p.valueEvidence.file).fileName())
            .arg(p.valueEvidence.line);
    if (p.source == QLatin1String("launch"))
        return tr("launch file");
    if (p.source == QLatin1String("default"))
        return tr("default");
    return p.declared ? tr("not set") : QString();
}

QVariant ParameterTableModel::data(const QModelIndex &index, int role) const
{
    const InstanceParameter *p = parameter(index);
    if (!p)
        return {};
    if (role == Qt::DisplayRole) {
        QString text;
        switch (index.column()) {
        case NameColumn:
            text = p->name;
            break;
        case TypeColumn:
            text = p->type;
            break;
        case DefaultColumn:
            text = p->hasDefault ? p->defaultValue : QString();
            break;
        case ValueColumn:
            text = p->source.isEmpty() ? QString() : p->value; // in effect: set, else default
            break;
        case SourceColumn:
            text = sourceText(*p);
            break;
        case DescriptionColumn:
            text = p->declared ? p->description : tr("not declared: ROS 2 ignores this value");
            break;
        default:
            break;
        }
        return visibleText(text);
    }
    if (role == Qt::ToolTipRole) {
        QStringList lines{p->name};
        if (!p->plugin.isEmpty())
            lines << tr("Declared by the plugin loaded as %1").arg(p->plugin);
        if (p->declaration.isValid())
            lines << tr("Declared at %1:%2").arg(p->declaration.file).arg(p->declaration.line);
        if (p->hasValue)
            lines << tr("Set at %1:%2").arg(p->valueEvidence.file).arg(p->valueEvidence.line);
        if (p->readOnly)
            lines << tr("Read-only");
        if (!p->range.isEmpty())
            lines << tr("Range: %1").arg(p->range);
        return visibleText(lines.join(u'\n'));
    }
    if (role == Qt::ForegroundRole && !p->declared)
        return QBrush(QPalette().color(QPalette::PlaceholderText));
    if (role == Qt::FontRole && index.column() == NameColumn && !p->declared) {
        QFont f;
        f.setItalic(true);
        return f;
    }
    const Evidence &where = p->hasValue ? p->valueEvidence : p->declaration;
    if (role == EvidenceFileRole)
        return where.file;
    if (role == EvidenceLineRole)
        return where.line;
    return {};
}

QVariant ParameterTableModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case NameColumn:
        return tr("Name");
    case TypeColumn:
        return tr("Type");
    case DefaultColumn:
        return tr("Default");
    case ValueColumn:
        return tr("Value");
    case SourceColumn:
        return tr("Source");
    case DescriptionColumn:
        return tr("Description");
    default:
        return {};
    }
}

QList<InstanceParameter>
ParameterTableModel::declaredOnly(const QList<ParameterDeclaration> &declared)
{
    QList<InstanceParameter> out;
    for (const ParameterDeclaration &d : declared) {
        InstanceParameter p = ParameterView::declared(d);
        p.source.clear(); // a class on its own: no value in effect
        p.value.clear();
        out.append(p);
    }
    return out;
}

} // namespace rosarch
