#include "widgets/suggestionmodel.h"
#include "document/document.h"
#include "jobs/stallprobe.h"

#include <QFileInfo>
#include <QFont>
#include <QGuiApplication>
#include <QIcon>
#include <QPainter>
#include <QPainterPath>
#include <QPalette>
#include <QPixmap>

namespace rosarch {

SuggestionModel::SuggestionModel(Document *document, QObject *parent)
    : QAbstractTableModel(parent), m_document(document)
{
    connect(document, &Document::aboutToChange, this, [this](const DocumentChange &change) {
        if (change.has(DocumentChange::Suggestions))
            beginResetModel();
    });
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        const StallScope scope("SuggestionModel (document changed)");
        if (change.has(DocumentChange::Suggestions)) {
            rebuildItems();
            endResetModel();
        } else if (change.has(DocumentChange::Suggestion)) {
            const QModelIndex first = indexOf(change.id);
            if (first.isValid())
                Q_EMIT dataChanged(first, index(first.row(), ColumnCount - 1));
        } else if (change.has(DocumentChange::Node) && rowCount() > 0) {
            // Targets show node names; a description edit can change the target column.
            Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
        }
    });
    rebuildItems();
}

void SuggestionModel::rebuildItems()
{
    m_items.clear();
    bool names = false;
    for (const Suggestion &s : m_document->session()->suggestions())
        names = names || s.kind == Suggestion::Kind::NameResolution;
    if (!names)
        return; // collecting walks the whole model; only name suggestions need it
    const Recovery recovery{m_document->atomicNodes(), m_document->launchDependencies(),
                            m_document->architecture()};
    for (const SuggestionItem &item : SuggestionItem::collect(recovery))
        m_items.insert(item.id, item);
}

int SuggestionModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_document->session()->suggestions().size());
}

int SuggestionModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

const Suggestion *SuggestionModel::suggestion(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this || index.row() < 0 ||
        index.row() >= m_document->session()->suggestions().size())
        return nullptr;
    return &m_document->session()->suggestions()[index.row()];
}

QModelIndex SuggestionModel::indexOf(const QString &id) const
{
    const QList<Suggestion> &list = m_document->session()->suggestions();
    for (qsizetype row = 0; row < list.size(); ++row)
        if (list[row].id == id)
            return index(int(row), 0);
    return {};
}

int SuggestionModel::count(Suggestion::Status status) const
{
    int n = 0;
    for (const Suggestion &s : m_document->session()->suggestions())
        n += s.status == status ? 1 : 0;
    return n;
}

int SuggestionModel::count(Suggestion::Status status, Suggestion::Kind kind) const
{
    int n = 0;
    for (const Suggestion &s : m_document->session()->suggestions())
        n += s.status == status && s.kind == kind ? 1 : 0;
    return n;
}

const SuggestionItem *SuggestionModel::item(const QString &itemId) const
{
    const auto it = m_items.constFind(itemId);
    return it == m_items.cend() ? nullptr : &*it;
}

QString SuggestionModel::kindLabel(Suggestion::Kind kind)
{
    switch (kind) {
    case Suggestion::Kind::NodeDescription:
        return tr("Description");
    case Suggestion::Kind::SubsystemGrouping:
        return tr("Grouping");
    case Suggestion::Kind::NameResolution:
        return tr("Name");
    }
    return {};
}

QString SuggestionModel::kindPlural(Suggestion::Kind kind)
{
    switch (kind) {
    case Suggestion::Kind::NodeDescription:
        return tr("Descriptions");
    case Suggestion::Kind::SubsystemGrouping:
        return tr("Groupings");
    case Suggestion::Kind::NameResolution:
        return tr("Names");
    }
    return {};
}

QString SuggestionModel::statusLabel(Suggestion::Status status)
{
    switch (status) {
    case Suggestion::Status::Pending:
        return tr("Pending");
    case Suggestion::Status::Accepted:
        return tr("Accepted");
    case Suggestion::Status::Rejected:
        return tr("Rejected");
    }
    return {};
}

QIcon SuggestionModel::statusIcon(Suggestion::Status status)
{
    const QPalette palette = QGuiApplication::palette();
    const qreal dpr = qGuiApp ? qGuiApp->devicePixelRatio() : 1.0;
    QPixmap pixmap(QSize(16, 16) * dpr);
    pixmap.setDevicePixelRatio(dpr);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF circle(2.5, 2.5, 11, 11);
    switch (status) {
    case Suggestion::Status::Pending: {
        // An amber ring: something to look at, visible on the selection colour as well.
        const QColor amber(0xe0, 0x8a, 0x00);
        p.setPen(QPen(amber, 1.6));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(circle);
        p.setBrush(amber);
        p.setPen(Qt::NoPen);
        p.drawEllipse(QRectF(6, 6, 4, 4));
        break;
    }
    case Suggestion::Status::Accepted: {
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0x2e, 0x9d, 0x5b));
        p.drawEllipse(circle);
        QPainterPath tick;
        tick.moveTo(5.3, 8.2);
        tick.lineTo(7.2, 10.2);
        tick.lineTo(10.8, 5.9);
        p.setPen(QPen(Qt::white, 1.7, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
        p.setBrush(Qt::NoBrush);
        p.drawPath(tick);
        break;
    }
    case Suggestion::Status::Rejected:
        p.setPen(Qt::NoPen);
        p.setBrush(palette.color(QPalette::Disabled, QPalette::Text));
        p.drawEllipse(circle);
        p.setPen(QPen(palette.color(QPalette::Base), 1.7, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(QPointF(5.8, 5.8), QPointF(10.2, 10.2));
        p.drawLine(QPointF(10.2, 5.8), QPointF(5.8, 10.2));
        break;
    }
    return QIcon(pixmap);
}

QString SuggestionModel::targetText(const Suggestion &s) const
{
    switch (s.kind) {
    case Suggestion::Kind::NodeDescription:
        if (const AtomicNode *n = m_document->atomicNodes().node(s.targetId))
            return n->className;
        return s.targetId;
    case Suggestion::Kind::SubsystemGrouping:
        return s.value;
    case Suggestion::Kind::NameResolution:
        if (const SuggestionItem *i = item(s.targetId); i && !i->expression.isEmpty())
            return i->expression;
        return s.targetId;
    }
    return s.targetId;
}

QString SuggestionModel::proposalText(const Suggestion &s) const
{
    if (s.quoted) // repository text is data: shown as a quotation, never as rosarch's words
        return tr("“%1” (quoted from the code)").arg(s.value);
    if (s.kind != Suggestion::Kind::SubsystemGrouping)
        return s.value;
    QStringList names;
    for (const QString &id : s.memberIds) {
        const NodeInstance *n = m_document->launchDependencies().node(id);
        names << (n && !n->nodeName.isEmpty() ? n->nodeName : id);
    }
    return names.join(QStringLiteral(", "));
}

QString SuggestionModel::evidenceText(const Suggestion &s)
{
    if (s.evidence.isEmpty())
        return {};
    const Evidence &e = s.evidence.first().evidence;
    QString text = QStringLiteral("%1:%2").arg(QFileInfo(e.file).fileName()).arg(e.line);
    if (s.evidence.size() > 1)
        text += QStringLiteral("  +%1").arg(s.evidence.size() - 1);
    return text;
}

QString SuggestionModel::originText(const Suggestion &s)
{
    return s.origin.provider == QLatin1String("deterministic") ? tr("deterministic")
                                                               : s.origin.provider;
}

QVariant SuggestionModel::data(const QModelIndex &index, int role) const
{
    const Suggestion *s = suggestion(index);
    if (!s)
        return {};
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case KindColumn:
            return kindLabel(s->kind);
        case TargetColumn:
            return targetText(*s);
        case ProposalColumn:
            return proposalText(*s);
        case OriginColumn:
            return originText(*s);
        case EvidenceColumn:
            return evidenceText(*s);
        default:
            return {};
        }
    case Qt::DecorationRole:
        return index.column() == KindColumn ? statusIcon(s->status) : QVariant();
    case Qt::ForegroundRole:
        if (s->status != Suggestion::Status::Pending)
            return QGuiApplication::palette().brush(QPalette::Disabled, QPalette::Text);
        return {};
    case Qt::FontRole:
        if (s->status == Suggestion::Status::Rejected && index.column() == ProposalColumn) {
            QFont font;
            font.setStrikeOut(true);
            return font;
        }
        return {};
    case Qt::ToolTipRole:
        switch (index.column()) {
        case KindColumn:
            return tr("%1 · %2").arg(Suggestion::kindName(s->kind), statusLabel(s->status));
        case TargetColumn:
            return s->targetId;
        case EvidenceColumn: {
            QStringList lines;
            for (const Suggestion::Citation &c : s->evidence)
                lines << QStringLiteral("%1:%2").arg(c.evidence.file).arg(c.evidence.line);
            return lines.join(QLatin1Char('\n'));
        }
        default:
            return s->rationale.isEmpty() ? QVariant() : QVariant(s->rationale);
        }
    case IdRole:
        return s->id;
    case StatusRole:
        return int(s->status);
    case KindRole:
        return int(s->kind);
    default:
        return {};
    }
}

QVariant SuggestionModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case KindColumn:
        return tr("Kind");
    case TargetColumn:
        return tr("Target");
    case ProposalColumn:
        return tr("Proposal");
    case OriginColumn:
        return tr("Origin");
    case EvidenceColumn:
        return tr("Evidence");
    default:
        return {};
    }
}

} // namespace rosarch
