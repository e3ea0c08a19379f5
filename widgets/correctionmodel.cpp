#include "widgets/correctionmodel.h"
#include "document/document.h"
#include "jobs/stallprobe.h"
#include "widgets/icons.h"

#include <QColor>
#include <QGuiApplication>
#include <QLocale>
#include <QPalette>

namespace rosarch {

CorrectionModel::CorrectionModel(Document *document, QObject *parent)
    : QAbstractTableModel(parent), m_document(document)
{
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        const StallScope scope("CorrectionModel (document changed)");
        // a re-run can orphan a correction or find its target again
        if (change.parts &
            (DocumentChange::Corrections | DocumentChange::Model | DocumentChange::Launch |
             DocumentChange::Decisions | DocumentChange::Accepted))
            refresh();
    });
    refresh();
}

void CorrectionModel::refresh()
{
    beginResetModel();
    m_corrections = m_document->session()->corrections();
    m_orphans.clear();
    if (!m_corrections.isEmpty())
        for (const Orphan &o : m_document->session()->orphans())
            if (o.source == Orphan::Source::Correction)
                m_orphans.insert(o.id, o.reason);
    endResetModel();
}

int CorrectionModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_corrections.size());
}

int CorrectionModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

int CorrectionModel::rowOf(const QString &id) const
{
    for (int i = 0; i < m_corrections.size(); ++i)
        if (m_corrections[i].id == id)
            return i;
    return -1;
}

QString CorrectionModel::orphanReason(const QString &id) const
{
    return m_orphans.value(id);
}

QString CorrectionModel::kindText(int kind)
{
    switch (Correction::Kind(kind)) {
    case Correction::Kind::Rename:
        return tr("Rename");
    case Correction::Kind::SetName:
        return tr("Set name");
    case Correction::Kind::SetType:
        return tr("Set type");
    case Correction::Kind::Remove:
        return tr("Remove");
    case Correction::Kind::AddPort:
        return tr("Add port");
    case Correction::Kind::AddPart:
        return tr("Add part");
    case Correction::Kind::AddConnection:
        return tr("Add connection");
    case Correction::Kind::Group:
        return tr("Group");
    case Correction::Kind::Review:
        return tr("Review");
    case Correction::Kind::Describe:
        return tr("Describe");
    }
    return {};
}

namespace {
QString change(const Correction &c)
{
    const QString arrow = QStringLiteral(" \u2192 ");
    switch (c.kind) {
    case Correction::Kind::Rename:
    case Correction::Kind::SetName:
    case Correction::Kind::SetType:
    case Correction::Kind::Describe:
        return c.oldValue + arrow + c.newValue;
    case Correction::Kind::Remove:
        return c.port.isEmpty() ? c.oldValue : c.oldValue + QStringLiteral(" (%1)").arg(c.port);
    case Correction::Kind::Review:
        return {};
    default:
        return arrow + c.summary();
    }
}
} // namespace

QVariant CorrectionModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.row() >= m_corrections.size())
        return {};
    const Correction &c = m_corrections[index.row()];
    const QString orphan = m_orphans.value(c.id);
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case KindColumn:
            return QStringLiteral("%1  %2").arg(c.id, kindText(int(c.kind)));
        case TargetColumn:
            return c.target;
        case ChangeColumn:
            return change(c);
        case ReasonColumn:
            return c.reason;
        case AuthorColumn:
            return c.author;
        case TimeColumn:
            return QLocale().toString(c.time.toLocalTime(), QLocale::ShortFormat);
        case StatusColumn:
            return orphan.isEmpty() ? tr("applied") : tr("orphaned: %1").arg(orphan);
        default:
            return {};
        }
    case Qt::ToolTipRole:
        if (!orphan.isEmpty())
            return tr("%1 matches nothing in this model and changes nothing: %2. Re-target it "
                      "to another element, or remove it.")
                .arg(c.id, orphan);
        if (index.column() == TimeColumn)
            return c.time.toString(Qt::ISODate);
        return c.summary();
    case Qt::DecorationRole:
        return index.column() == KindColumn && !orphan.isEmpty() ? Icons::unresolved() : QVariant();
    case Qt::ForegroundRole:
        // quiet: a warm muted tone, not an error red
        if (!orphan.isEmpty())
            return QGuiApplication::palette().color(QPalette::Window).lightness() < 128
                       ? QColor(0xe0, 0xb0, 0x60)
                       : QColor(0x9a, 0x67, 0x00);
        return {};
    case IdRole:
        return c.id;
    case TargetRole:
        return c.target;
    case OrphanedRole:
        return !orphan.isEmpty();
    default:
        return {};
    }
}

QVariant CorrectionModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case KindColumn:
        return tr("Correction");
    case TargetColumn:
        return tr("Target");
    case ChangeColumn:
        return tr("Old \u2192 new");
    case ReasonColumn:
        return tr("Reason");
    case AuthorColumn:
        return tr("Author");
    case TimeColumn:
        return tr("Time");
    case StatusColumn:
        return tr("Status");
    default:
        return {};
    }
}

} // namespace rosarch
