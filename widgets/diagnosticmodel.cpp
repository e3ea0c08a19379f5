#include "diagnosticmodel.h"
#include "document.h"
#include "icons.h"

namespace rosarch {

DiagnosticModel::DiagnosticModel(Document *document, QObject *parent)
    : QAbstractTableModel(parent), m_document(document)
{
    // Diagnostics come with stage results: only a new model or a stage 2 run changes them.
    connect(document, &Document::aboutToChange, this, [this](const DocumentChange &change) {
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch))
            beginResetModel();
    });
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch))
            endResetModel();
    });
}

int DiagnosticModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0
                            : int(m_document->atomicNodes().diagnostics.size() +
                                  m_document->launchDependencies().diagnostics.size() +
                                  m_document->architecture().diagnostics.size());
}

int DiagnosticModel::columnCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : ColumnCount;
}

const Diagnostic *DiagnosticModel::diagnostic(const QModelIndex &index) const
{
    if (!index.isValid() || index.model() != this || index.row() < 0)
        return nullptr;
    // Stage 1's diagnostics, then stage 2's, then stage 3's.
    qsizetype row = index.row();
    for (const QList<Diagnostic> *list :
         {&m_document->atomicNodes().diagnostics, &m_document->launchDependencies().diagnostics,
          &m_document->architecture().diagnostics}) {
        if (row < list->size())
            return &(*list)[row];
        row -= list->size();
    }
    return nullptr;
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
    const Diagnostic *d = diagnostic(index);
    if (!d)
        return {};
    const QString where = d->evidence.isValid()
                              ? QStringLiteral("%1:%2").arg(d->evidence.file).arg(d->evidence.line)
                              : d->evidence.file;
    switch (role) {
    case Qt::DisplayRole:
        switch (index.column()) {
        case MessageColumn:
            return d->message;
        case LocationColumn:
            return where;
        case CodeColumn:
            return d->code;
        default:
            return {};
        }
    case Qt::DecorationRole:
        return index.column() == MessageColumn ? Icons::severity(d->severity) : QVariant();
    case Qt::ToolTipRole: {
        QString tip = QStringLiteral("<b>%1</b> (%2)<br/>%3")
                          .arg(severityLabel(d->severity), d->code.toHtmlEscaped(),
                               d->message.toHtmlEscaped());
        if (!where.isEmpty())
            tip += QStringLiteral("<br/>") + tr("At %1").arg(where.toHtmlEscaped());
        return tip;
    }
    default:
        return {};
    }
}

QVariant DiagnosticModel::headerData(int section, Qt::Orientation orientation, int role) const
{
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    switch (section) {
    case MessageColumn:
        return tr("Message");
    case LocationColumn:
        return tr("Location");
    case CodeColumn:
        return tr("Code");
    default:
        return {};
    }
}

} // namespace rosarch
