#include "logview.h"
#include "diagnosticmodel.h"

#include <QFontDatabase>
#include <QHeaderView>
#include <QPlainTextEdit>
#include <QSplitter>
#include <QTime>
#include <QTreeView>
#include <QVBoxLayout>

namespace rosarch {

LogView::LogView(QWidget *parent)
    : QWidget(parent), m_splitter(new QSplitter(Qt::Horizontal, this)),
      m_diagnostics(new QTreeView(m_splitter)), m_log(new QPlainTextEdit(m_splitter))
{
    m_diagnostics->setRootIsDecorated(false);
    m_diagnostics->setUniformRowHeights(true);
    m_diagnostics->setAlternatingRowColors(true);
    m_diagnostics->setAllColumnsShowFocus(true);
    m_diagnostics->setSelectionMode(QAbstractItemView::SingleSelection);
    m_diagnostics->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_diagnostics->setFrameShape(QFrame::NoFrame);
    m_diagnostics->setToolTip(QString());
    connect(m_diagnostics, &QTreeView::activated, this, &LogView::onCurrentChanged);

    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(5000);
    m_log->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_log->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_log->setPlaceholderText(tr("Progress and messages of stage runs appear here."));
    m_log->setFrameShape(QFrame::NoFrame);

    m_splitter->addWidget(m_diagnostics);
    m_splitter->addWidget(m_log);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);
}

void LogView::setModel(DiagnosticModel *model)
{
    m_model = model;
    m_diagnostics->setModel(model);
    m_diagnostics->header()->setStretchLastSection(false);
    m_diagnostics->header()->setSectionResizeMode(DiagnosticModel::MessageColumn,
                                                  QHeaderView::Stretch);
    m_diagnostics->header()->setSectionResizeMode(DiagnosticModel::LocationColumn,
                                                  QHeaderView::Interactive);
    m_diagnostics->header()->setSectionResizeMode(DiagnosticModel::CodeColumn,
                                                  QHeaderView::Interactive);
    m_diagnostics->setColumnWidth(DiagnosticModel::LocationColumn, 260);
    m_diagnostics->setColumnWidth(DiagnosticModel::CodeColumn, 150);
    connect(m_diagnostics->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &LogView::onCurrentChanged);
}

void LogView::appendLog(const QString &line)
{
    m_log->appendPlainText(QStringLiteral("%1  %2").arg(
        QTime::currentTime().toString(QStringLiteral("HH:mm:ss")), line));
}

void LogView::clearLog()
{
    m_log->clear();
}

void LogView::selectNextDiagnostic()
{
    step(1);
}

void LogView::selectPreviousDiagnostic()
{
    step(-1);
}

void LogView::step(int delta)
{
    if (!m_model || m_model->rowCount() == 0)
        return;
    const int rows = m_model->rowCount();
    const QModelIndex current = m_diagnostics->currentIndex();
    int row = current.isValid() ? current.row() + delta : (delta > 0 ? 0 : rows - 1);
    row = (row + rows) % rows;
    const QModelIndex next = m_model->index(row, 0);
    m_diagnostics->selectionModel()->setCurrentIndex(next, QItemSelectionModel::ClearAndSelect |
                                                               QItemSelectionModel::Rows);
    m_diagnostics->scrollTo(next);
    // Re-selecting the same row (a single diagnostic) should still show it again.
    if (current == next)
        onCurrentChanged(next);
}

void LogView::onCurrentChanged(const QModelIndex &current)
{
    const Diagnostic *d = m_model ? m_model->diagnostic(current) : nullptr;
    if (d && d->evidence.isValid())
        Q_EMIT evidenceRequested(d->evidence);
}

} // namespace rosarch
