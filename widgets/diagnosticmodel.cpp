#include "widgets/diagnosticmodel.h"
#include "core/diagnostickind.h"
#include "core/visibletext.h"
#include "document/document.h"
#include "jobs/stallprobe.h"
#include "widgets/icons.h"
#include "widgets/treeindexid.h"

#include <QColor>
#include <QFont>

#include <algorithm>
#include <limits>

namespace rosarch {

namespace {

// A row's internal id: a top-level row (a group, or a finding when not grouped), or a finding
// in the group whose row is the payload.
enum class RowTag
{
    TopLevel,
    InGroup
};
using RowId = TreeIndexId<RowTag, 1>;
// Every group row an int can number fits in an id, even where quintptr has 32 bits.
static_assert(RowId::kMaxPayload >= std::numeric_limits<int>::max());

bool isTopLevel(const QModelIndex &index)
{
    return RowId::of(index).tag() == RowTag::TopLevel;
}

int rank(Diagnostic::Severity s)
{
    return s == Diagnostic::Severity::Error ? 2 : s == Diagnostic::Severity::Warning ? 1 : 0;
}

QString place(const Evidence &e)
{
    const QString file = visibleText(e.file); // one line, whatever the name holds
    return e.isValid() ? QStringLiteral("%1:%2").arg(file).arg(e.line) : file;
}

} // namespace

DiagnosticModel::DiagnosticModel(Document *document, QObject *parent)
    : QAbstractItemModel(parent), m_document(document)
{
    // Diagnostics come with stage results (a new model, a stage 2 run); stage 3's are those of
    // the corrected model, so corrections and accepted suggestions change them too.
    connect(document, &Document::aboutToChange, this, [this](const DocumentChange &change) {
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch))
            beginResetModel();
    });
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        const StallScope scope("DiagnosticModel (document changed)");
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch)) {
            reload();
            endResetModel();
            Q_EMIT findingsChanged();
        } else if (change.parts & (DocumentChange::Corrections | DocumentChange::Decisions |
                                   DocumentChange::Accepted)) {
            if (m_document->isAcceptedPending())
                return; // DocumentChange::Accepted follows
            beginResetModel();
            reload();
            endResetModel();
            Q_EMIT findingsChanged();
        } else if (change.has(DocumentChange::Findings)) {
            refresh();
        }
    });
    reload();
}

void DiagnosticModel::reload()
{
    m_entries.clear();
    m_architectureDiagnostics = m_document->accepted().architecture.diagnostics;
    // A file's package: the deepest package folder holding it.
    QHash<QString, QString> packages;
    for (const RosPackage &p : m_document->atomicNodes().packages)
        packages.insert(p.path, p.name);
    QHash<QString, QString> folderPackage;
    for (const QList<Diagnostic> *list : std::initializer_list<const QList<Diagnostic> *>{
             &m_document->atomicNodes().diagnostics, &m_document->launchDependencies().diagnostics,
             &m_architectureDiagnostics})
        for (const Diagnostic &d : *list) {
            QString folder = d.evidence.file.section(QLatin1Char('/'), 0, -2);
            QString package;
            if (const auto it = folderPackage.constFind(folder); it != folderPackage.cend()) {
                package = *it;
            } else {
                for (QString f = folder;; f = f.section(QLatin1Char('/'), 0, -2)) {
                    if (const auto p = packages.constFind(f); p != packages.cend()) {
                        package = *p;
                        break;
                    }
                    if (f.isEmpty())
                        break;
                }
                folderPackage.insert(folder, package);
            }
            m_entries.append({&d, {}, package});
        }
    rebuild();
}

const QString &DiagnosticModel::keyOf(const Entry &e) const
{
    if (e.key.isEmpty())
        e.key = e.diagnostic->key(); // a hash of its text: ~1,500 of them took milliseconds
    return e.key;
}

void DiagnosticModel::refresh()
{
    beginResetModel();
    rebuild();
    endResetModel();
    Q_EMIT findingsChanged();
}

bool DiagnosticModel::isShownMark(const Entry &e) const
{
    if (e.mark < 0)
        return true;
    const FindingMark &m = m_document->session()->findingMarks().at(e.mark);
    return m.status == FindingMark::Status::Accepted ? m_filter.showAccepted : m_filter.showHidden;
}

bool DiagnosticModel::passes(const Entry &e, bool ignoreCode, bool ignorePackage) const
{
    const Diagnostic &d = *e.diagnostic;
    const bool severity = d.severity == Diagnostic::Severity::Error     ? m_filter.errors
                          : d.severity == Diagnostic::Severity::Warning ? m_filter.warnings
                                                                        : m_filter.infos;
    if (!severity || !isShownMark(e))
        return false;
    if (!ignoreCode && !m_filter.code.isEmpty() && d.code != m_filter.code)
        return false;
    if (!ignorePackage && !m_filter.package.isEmpty() && e.package != m_filter.package)
        return false;
    if (m_filter.text.isEmpty())
        return true;
    const auto has = [&](const QString &s) {
        return s.contains(m_filter.text, Qt::CaseInsensitive);
    };
    return has(d.message) || has(d.evidence.file) || has(d.code) || has(e.package) ||
           has(DiagnosticKind::of(d.code).title);
}

void DiagnosticModel::rebuild()
{
    QHash<QString, int> marks;
    const QList<FindingMark> &all = m_document->session()->findingMarks();
    for (int i = 0; i < all.size(); ++i)
        marks.insert(all.at(i).key, i);
    m_visible.clear();
    m_groups.clear();
    QHash<QString, int> groupOf;
    for (int i = 0; i < m_entries.size(); ++i) {
        Entry &e = m_entries[i];
        e.mark = marks.isEmpty() ? -1 : marks.value(keyOf(e), -1);
        for (int a = 0; e.mark < 0 && !marks.isEmpty() && a < e.diagnostic->aliases.size(); ++a)
            e.mark = marks.value(e.diagnostic->aliases.at(a), -1);
        if (!passes(e, false, false))
            continue;
        m_visible.append(i);
        if (m_grouping == Grouping::None)
            continue;
        const QString group = m_grouping == Grouping::Kind ? e.diagnostic->code : e.package;
        auto it = groupOf.constFind(group);
        if (it == groupOf.cend()) {
            it = groupOf.insert(group, int(m_groups.size()));
            m_groups.append({group, {}});
        }
        m_groups[*it].entries.append(i);
    }
}

void DiagnosticModel::setFilter(const Filter &filter)
{
    if (filter == m_filter)
        return;
    m_filter = filter;
    refresh();
}

void DiagnosticModel::setGrouping(Grouping grouping)
{
    if (grouping == m_grouping)
        return;
    m_grouping = grouping;
    refresh();
}

QMap<QString, int> DiagnosticModel::codeCounts() const
{
    QMap<QString, int> out;
    for (const Entry &e : m_entries)
        if (passes(e, true, false))
            ++out[e.diagnostic->code];
    return out;
}

QMap<QString, int> DiagnosticModel::packageCounts() const
{
    QMap<QString, int> out;
    for (const Entry &e : m_entries)
        if (passes(e, false, true))
            ++out[e.package];
    return out;
}

int DiagnosticModel::severityCount(Diagnostic::Severity severity) const
{
    return int(std::count_if(m_entries.cbegin(), m_entries.cend(), [&](const Entry &e) {
        return e.diagnostic->severity == severity && isShownMark(e);
    }));
}

QModelIndex DiagnosticModel::index(int row, int column, const QModelIndex &parent) const
{
    if (row < 0 || column < 0 || column >= ColumnCount || row >= rowCount(parent))
        return {};
    if (!parent.isValid())
        return createIndex(row, column, RowId(RowTag::TopLevel).internalId());
    return createIndex(row, column, RowId(RowTag::InGroup, parent.row()).internalId());
}

QModelIndex DiagnosticModel::parent(const QModelIndex &child) const
{
    if (!child.isValid() || isTopLevel(child))
        return {};
    return createIndex(int(RowId::of(child).payload()), 0, RowId(RowTag::TopLevel).internalId());
}

int DiagnosticModel::rowCount(const QModelIndex &parent) const
{
    if (!parent.isValid())
        return int(m_grouping == Grouping::None ? m_visible.size() : m_groups.size());
    if (parent.column() != 0 || !isTopLevel(parent) || m_grouping == Grouping::None)
        return 0;
    return int(m_groups.at(parent.row()).entries.size());
}

int DiagnosticModel::columnCount(const QModelIndex &) const
{
    return ColumnCount;
}

int DiagnosticModel::entryAt(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this)
        return -1;
    if (m_grouping == Grouping::None)
        return m_visible.value(index.row(), -1);
    if (isTopLevel(index))
        return -1;
    return m_groups.at(int(RowId::of(index).payload())).entries.value(index.row(), -1);
}

const Diagnostic *DiagnosticModel::diagnostic(const QModelIndex &index) const
{
    const int e = entryAt(index);
    return e < 0 ? nullptr : m_entries.at(e).diagnostic;
}

QString DiagnosticModel::package(const QModelIndex &index) const
{
    const int e = entryAt(index);
    return e < 0 ? QString() : m_entries.at(e).package;
}

std::optional<FindingMark> DiagnosticModel::mark(const QModelIndex &index) const
{
    const int e = entryAt(index);
    if (e < 0 || m_entries.at(e).mark < 0)
        return std::nullopt;
    return m_document->session()->findingMarks().value(m_entries.at(e).mark);
}

QString DiagnosticModel::severityLabel(Diagnostic::Severity severity)
{
    switch (severity) {
    case Diagnostic::Severity::Info:
        return tr("Info");
    case Diagnostic::Severity::Warning:
        return tr("Warning");
    case Diagnostic::Severity::Error:
        return tr("Error");
    }
    return {};
}

QVariant DiagnosticModel::data(const QModelIndex &index, int role) const
{
    if (!index.isValid() || index.model() != this)
        return {};
    const bool isGroup = m_grouping != Grouping::None && isTopLevel(index);
    if (isGroup) {
        const Group &g = m_groups.at(index.row());
        QString label = g.label;
        if (m_grouping == Grouping::Kind)
            label = QStringLiteral("%1 — %2").arg(g.label, DiagnosticKind::of(g.label).title);
        else if (label.isEmpty())
            label = tr("(no package)");
        switch (role) {
        case Qt::DisplayRole:
            // Explicit singular/plural: no translator is loaded for English.
            if (index.column() != 0)
                return {};
            return g.entries.size() == 1 ? tr("%1 (1 finding)").arg(label)
                                         : tr("%1 (%2 findings)").arg(label).arg(g.entries.size());
        case SortRole:
            if (index.column() == SeverityColumn) { // by the worst finding in the group
                int worst = 0;
                for (int at : g.entries)
                    worst = std::max(worst, rank(m_entries.at(at).diagnostic->severity));
                return worst;
            }
            return index.column() == ContextsColumn ? QVariant(int(g.entries.size()))
                                                    : QVariant(label);
        case GroupRole:
            return true;
        case Qt::FontRole: {
            QFont f;
            f.setBold(true);
            return f;
        }
        default:
            return {};
        }
    }
    const int at = entryAt(index);
    if (at < 0)
        return {};
    const Entry &e = m_entries.at(at);
    const Diagnostic &d = *e.diagnostic;
    const std::optional<FindingMark> m = mark(index);
    const bool accepted = m && m->status == FindingMark::Status::Accepted;
    const bool hidden = m && !accepted;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case SeverityColumn:
            if (m)
                return accepted ? tr("%1 (accepted)").arg(severityLabel(d.severity))
                                : tr("%1 (hidden)").arg(severityLabel(d.severity));
            return severityLabel(d.severity);
        case KindColumn:
            return QStringLiteral("%1 — %2").arg(d.code, DiagnosticKind::of(d.code).title);
        case PackageColumn:
            return e.package;
        case FileColumn:
            return place(d.evidence);
        case MessageColumn:
            return visibleText(d.message);
        case ContextsColumn:
            return d.contexts.isEmpty() ? QVariant() : QVariant(int(d.contexts.size()));
        default:
            return {};
        }
    case SortRole:
        switch (index.column()) {
        case SeverityColumn:
            return rank(d.severity);
        case FileColumn:
            return QStringLiteral("%1:%2")
                .arg(d.evidence.file)
                .arg(d.evidence.line, 8, 10, QLatin1Char('0'));
        case ContextsColumn:
            return int(d.contexts.size());
        default:
            return data(index, Qt::DisplayRole);
        }
    case KeyRole:
        return keyOf(e);
    case GroupRole:
        return false;
    // An accepted finding was looked at and is fine: a tick, in the normal colour. A hidden one
    // was set aside: greyed and italic.
    case Qt::DecorationRole:
        if (index.column() != SeverityColumn)
            return {};
        return accepted ? Icons::accepted() : Icons::severity(d.severity);
    case Qt::ForegroundRole:
        return hidden ? QVariant(QColor(Qt::gray)) : QVariant();
    case Qt::FontRole:
        if (hidden) {
            QFont f;
            f.setItalic(true);
            return f;
        }
        return {};
    case Qt::ToolTipRole: {
        QString tip =
            QStringLiteral("<b>%1</b> (%2)<br/>%3")
                .arg(severityLabel(d.severity), d.code.toHtmlEscaped(), d.message.toHtmlEscaped());
        if (!d.evidence.file.isEmpty())
            tip += QStringLiteral("<br/>") + tr("At %1").arg(place(d.evidence).toHtmlEscaped());
        if (d.contexts.size() > 1)
            tip += QStringLiteral("<br/>") + tr("Seen in %1 systems").arg(d.contexts.size());
        if (m) {
            const QString who = m->author.isEmpty() ? tr("someone") : m->author;
            tip += QStringLiteral("<br/><i>") +
                   (accepted ? tr("Accepted by %1") : tr("Hidden by %1")).arg(who.toHtmlEscaped());
            if (!m->reason.isEmpty())
                tip += QStringLiteral(": ") + m->reason.toHtmlEscaped();
            tip += QStringLiteral("</i>");
        }
        return tip;
    }
    default:
        return {};
    }
}

QVariant DiagnosticModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal)
        return {};
    if (role == Qt::ToolTipRole && section == ContextsColumn)
        return tr("The number of systems (root launch files) the finding was seen in");
    if (role != Qt::DisplayRole)
        return {};
    switch (section) {
    case SeverityColumn:
        return tr("Severity");
    case KindColumn:
        return tr("Kind");
    case PackageColumn:
        return tr("Package");
    case FileColumn:
        return tr("File");
    case MessageColumn:
        return tr("Message");
    case ContextsColumn:
        return tr("Systems");
    default:
        return {};
    }
}

QStringList DiagnosticModel::keysAt(const QModelIndexList &indexes) const
{
    QStringList keys;
    const auto add = [&](int e) {
        if (e >= 0 && !keys.contains(keyOf(m_entries.at(e))))
            keys.append(keyOf(m_entries.at(e)));
    };
    for (const QModelIndex &i : indexes) {
        if (i.model() != this)
            continue;
        if (m_grouping != Grouping::None && i.isValid() && isTopLevel(i)) {
            for (int e : m_groups.at(i.row()).entries)
                add(e);
        } else {
            add(entryAt(i));
        }
    }
    return keys;
}

int DiagnosticModel::markFindings(const QModelIndexList &indexes, FindingMark::Status status,
                                  const QString &reason)
{
    return m_document->session()->markFindings(keysAt(indexes), status, reason);
}

int DiagnosticModel::restoreFindings(const QModelIndexList &indexes)
{
    // A mark may be stored under an alias (a key the finding had before): remove that one.
    QStringList keys;
    const QStringList own = keysAt(indexes);
    for (const Entry &e : std::as_const(m_entries))
        if (e.mark >= 0 && own.contains(keyOf(e)))
            keys.append(m_document->session()->findingMarks().at(e.mark).key);
    return m_document->session()->unmarkFindings(keys);
}

} // namespace rosarch
