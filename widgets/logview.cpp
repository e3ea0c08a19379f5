#include "widgets/logview.h"
#include "widgets/diagnosticdetail.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagnosticmodel.h"

#include <QAction>
#include <QFontDatabase>
#include <QHeaderView>
#include <QInputDialog>
#include <QItemSelectionModel>
#include <QLocale>
#include <QPlainTextEdit>
#include <QSortFilterProxyModel>
#include <QSplitter>
#include <QTime>
#include <QTreeView>
#include <QVBoxLayout>

namespace rosarch {

LogView::LogView(QWidget *parent)
    : QWidget(parent), m_proxy(new QSortFilterProxyModel(this)),
      m_splitter(new QSplitter(Qt::Horizontal, this)), m_findings(new QWidget(m_splitter)),
      m_findingsSplitter(new QSplitter(Qt::Vertical, m_findings)),
      m_diagnostics(new QTreeView(m_findingsSplitter)),
      m_detail(new DiagnosticDetail(m_findingsSplitter)), m_log(new QPlainTextEdit(m_splitter)),
      m_hide(new QAction(tr("&Hide Finding"), this)),
      m_accept(new QAction(tr("&Accept Finding"), this)),
      m_acceptWithReason(new QAction(tr("Accept Finding with &Reason\u2026"), this)),
      m_restore(new QAction(tr("Re&store Finding"), this)),
      m_acceptExternal(new QAction(tr("Accept as E&xpected External"), this))
{
    m_proxy->setSortRole(DiagnosticModel::SortRole);
    m_proxy->setSortCaseSensitivity(Qt::CaseInsensitive);

    m_diagnostics->setUniformRowHeights(true);
    m_diagnostics->setAlternatingRowColors(true);
    m_diagnostics->setAllColumnsShowFocus(true);
    m_diagnostics->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_diagnostics->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_diagnostics->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_diagnostics->setFrameShape(QFrame::NoFrame);
    m_diagnostics->setToolTip(QString());
    m_diagnostics->setContextMenuPolicy(Qt::ActionsContextMenu);
    connect(m_diagnostics, &QTreeView::activated, this, &LogView::onCurrentChanged);

    // Single keys while the table has the focus: a findings table has no use for type-ahead.
    m_hide->setShortcuts({QKeySequence(tr("H")), QKeySequence(QKeySequence::Delete)});
    m_hide->setToolTip(tr("Hide the selected findings: they leave the list (Hidden shows them)"));
    m_accept->setShortcut(QKeySequence(tr("A")));
    m_accept->setToolTip(tr("Accept the selected findings as they are: they leave the list and "
                            "rosarch check no longer counts them as new"));
    m_restore->setShortcut(QKeySequence(tr("U")));
    m_restore->setToolTip(tr("Show the selected hidden or accepted findings again"));
    m_acceptExternal->setShortcut(QKeySequence(tr("X")));
    m_acceptExternal->setToolTip(
        tr("Declare the port of the selected findings as meeting something outside the "
           "workspace (a driver, teleoperation, a tool): the project records it and the checks "
           "no longer report it in any system"));
    m_acceptExternal->setEnabled(false);
    for (QAction *a : {m_hide, m_accept, m_acceptWithReason, m_acceptExternal, m_restore}) {
        a->setShortcutContext(Qt::WidgetShortcut);
        m_diagnostics->addAction(a);
    }
    connect(m_hide, &QAction::triggered, this,
            [this] { markSelected(int(FindingMark::Status::Hidden), false); });
    connect(m_accept, &QAction::triggered, this,
            [this] { markSelected(int(FindingMark::Status::Accepted), false); });
    connect(m_acceptWithReason, &QAction::triggered, this,
            [this] { markSelected(int(FindingMark::Status::Accepted), true); });
    connect(m_acceptExternal, &QAction::triggered, this, [this] {
        const QStringList declarations = selectedExternals();
        if (!declarations.isEmpty())
            Q_EMIT externalsAccepted(declarations);
    });
    connect(m_restore, &QAction::triggered, this, [this] {
        if (m_model)
            m_model->restoreFindings(selectedFindings());
    });
    connect(m_detail, &DiagnosticDetail::evidenceRequested, this, &LogView::evidenceRequested);

    m_findingsSplitter->addWidget(m_diagnostics);
    m_findingsSplitter->addWidget(m_detail);
    m_findingsSplitter->setStretchFactor(0, 3);
    m_findingsSplitter->setStretchFactor(1, 1);
    m_findingsSplitter->setChildrenCollapsible(false);
    auto *findingsLayout = new QVBoxLayout(m_findings);
    findingsLayout->setContentsMargins(0, 0, 0, 0);
    findingsLayout->setSpacing(0);
    findingsLayout->addWidget(m_findingsSplitter);

    m_log->setReadOnly(true);
    m_log->setMaximumBlockCount(5000);
    // Wrapped: the pane is narrow beside the findings, and a cut line hid the stage times.
    m_log->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    m_log->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    m_log->setPlaceholderText(tr("Progress and messages of stage runs appear here."));
    m_log->setFrameShape(QFrame::NoFrame);

    m_splitter->addWidget(m_findings);
    m_splitter->addWidget(m_log);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 1);
    // The run log keeps a readable share (about 30 characters) in the default layout: the
    // filter bar above the findings would otherwise take the whole width.
    m_log->setMinimumWidth(m_log->fontMetrics().horizontalAdvance(QLatin1Char('0')) * 30);
    m_splitter->setChildrenCollapsible(false);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);
}

void LogView::setModel(DiagnosticModel *model)
{
    m_model = model;
    m_proxy->setSourceModel(model);
    m_filterBar = new DiagnosticFilterBar(model, m_findings);
    static_cast<QVBoxLayout *>(m_findings->layout())->insertWidget(0, m_filterBar);
    m_diagnostics->setModel(m_proxy);
    const auto updateExternal = [this] {
        m_acceptExternal->setEnabled(!selectedExternals().isEmpty());
    };
    connect(m_diagnostics->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            updateExternal);
    connect(m_diagnostics->selectionModel(), &QItemSelectionModel::currentChanged, this,
            updateExternal);
    connect(m_proxy, &QAbstractItemModel::modelReset, this, updateExternal);
    QHeaderView *header = m_diagnostics->header();
    header->setStretchLastSection(false);
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->setSectionResizeMode(DiagnosticModel::MessageColumn, QHeaderView::Stretch);
    m_diagnostics->setColumnWidth(DiagnosticModel::SeverityColumn, 110);
    m_diagnostics->setColumnWidth(DiagnosticModel::KindColumn, 220);
    m_diagnostics->setColumnWidth(DiagnosticModel::PackageColumn, 130);
    m_diagnostics->setColumnWidth(DiagnosticModel::FileColumn, 240);
    m_diagnostics->setColumnWidth(DiagnosticModel::ContextsColumn, 60);
    // Sorted only once a header is clicked: until then, the order the stages found them in.
    // (Sorted by severity at every result, autoware's 1,271 findings gave UI stalls of 35-55
    // ms in the stall benchmark, against 30-37 ms unsorted: too close to the 50 ms budget.)
    header->setSectionsClickable(true);
    header->setSortIndicatorShown(true);
    header->setSortIndicator(-1, Qt::AscendingOrder);
    connect(header, &QHeaderView::sortIndicatorChanged, m_proxy,
            [this](int column, Qt::SortOrder order) { m_proxy->sort(column, order); });
    connect(m_diagnostics->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &LogView::onCurrentChanged);
    connect(m_proxy, &QAbstractItemModel::modelReset, this, &LogView::afterReset);
    connect(model, &DiagnosticModel::findingsChanged, this,
            [this] { Q_EMIT titleChanged(title()); });
    afterReset();
}

QString LogView::title() const
{
    if (!m_model || m_model->total() == 0)
        return tr("Log");
    const QLocale locale;
    if (m_model->shown() == m_model->total())
        return tr("Log — %1 findings").arg(locale.toString(m_model->total()));
    return tr("Log — %1 findings, %2 shown")
        .arg(locale.toString(m_model->total()), locale.toString(m_model->shown()));
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

void LogView::afterReset()
{
    // Group rows span the table and start open; the finding selected before stays selected
    // when it is still shown.
    // (A reset clears the spans: ungrouped, there is nothing to undo.)
    const bool grouped = m_model && m_model->grouping() != DiagnosticModel::Grouping::None;
    if (grouped) {
        for (int row = 0; row < m_proxy->rowCount(); ++row)
            m_diagnostics->setFirstColumnSpanned(row, {}, true);
        m_diagnostics->expandAll();
    }
    m_diagnostics->setRootIsDecorated(grouped);
    if (grouped != m_grouped) { // under a group the severity is indented: its column widens
        const int indent = m_diagnostics->indentation();
        m_diagnostics->setColumnWidth(DiagnosticModel::SeverityColumn,
                                      m_diagnostics->columnWidth(DiagnosticModel::SeverityColumn) +
                                          (grouped ? indent : -indent));
        m_grouped = grouped;
    }
    const QString key = m_currentKey;
    if (!key.isEmpty()) {
        const QModelIndexList found = m_proxy->match(m_proxy->index(0, 0), DiagnosticModel::KeyRole,
                                                     key, 1, Qt::MatchExactly | Qt::MatchRecursive);
        if (!found.isEmpty()) {
            m_diagnostics->selectionModel()->setCurrentIndex(
                found.first(), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
            m_diagnostics->scrollTo(found.first());
            return;
        }
    }
    showCurrent();
}

void LogView::step(int delta)
{
    if (!m_model)
        return;
    // The findings in the order the view shows them: the proxy's sort, under their groups.
    QModelIndexList order;
    for (int row = 0; row < m_proxy->rowCount(); ++row) {
        const QModelIndex top = m_proxy->index(row, 0);
        if (top.data(DiagnosticModel::GroupRole).toBool()) {
            for (int child = 0; child < m_proxy->rowCount(top); ++child)
                order.append(m_proxy->index(child, 0, top));
        } else {
            order.append(top);
        }
    }
    if (order.isEmpty())
        return;
    const QModelIndex current = m_diagnostics->currentIndex().siblingAtColumn(0);
    const qsizetype at = order.indexOf(current);
    const qsizetype rows = order.size();
    qsizetype row = at >= 0 ? at + delta : (delta > 0 ? 0 : rows - 1);
    row = (row + rows) % rows;
    const QModelIndex next = order.at(row);
    m_diagnostics->selectionModel()->setCurrentIndex(next, QItemSelectionModel::ClearAndSelect |
                                                               QItemSelectionModel::Rows);
    m_diagnostics->scrollTo(next);
    // Re-selecting the same row (a single finding) should still show it again.
    if (current == next)
        onCurrentChanged(next);
}

void LogView::showCurrent()
{
    const QModelIndex source = m_proxy->mapToSource(m_diagnostics->currentIndex());
    const Diagnostic *d = m_model ? m_model->diagnostic(source) : nullptr;
    if (!d) {
        m_detail->showFinding(std::nullopt);
        return;
    }
    m_detail->showFinding(*d, m_model->package(source), m_model->mark(source));
}

void LogView::onCurrentChanged(const QModelIndex &current)
{
    const QModelIndex source = m_proxy->mapToSource(current);
    const Diagnostic *d = m_model ? m_model->diagnostic(source) : nullptr;
    if (d)
        m_currentKey = current.data(DiagnosticModel::KeyRole).toString();
    showCurrent();
    if (d && d->evidence.isValid())
        Q_EMIT evidenceRequested(d->evidence);
}

QModelIndexList LogView::selectedFindings() const
{
    QModelIndexList out;
    for (const QModelIndex &i : m_diagnostics->selectionModel()->selectedRows())
        out.append(m_proxy->mapToSource(i));
    if (out.isEmpty() && m_diagnostics->currentIndex().isValid())
        out.append(m_proxy->mapToSource(m_diagnostics->currentIndex()));
    return out;
}

QStringList LogView::selectedExternals() const
{
    QStringList out;
    if (!m_model)
        return out;
    for (const QModelIndex &i : selectedFindings())
        if (const Diagnostic *d = m_model->diagnostic(i);
            d && !d->external.isEmpty() && !out.contains(d->external))
            out.append(d->external);
    return out;
}

void LogView::markSelected(int status, bool askReason)
{
    if (!m_model)
        return;
    const QModelIndexList findings = selectedFindings();
    if (findings.isEmpty())
        return;
    QString reason;
    if (askReason) {
        bool ok = false;
        reason = QInputDialog::getText(this, tr("Accept Finding"),
                                       tr("Why is this finding fine as it is?"), QLineEdit::Normal,
                                       QString(), &ok);
        if (!ok)
            return;
    }
    // The next finding shown takes the selection, so a person can work down the list.
    const QModelIndex below = m_diagnostics->indexBelow(m_diagnostics->currentIndex());
    m_currentKey = below.data(DiagnosticModel::KeyRole).toString();
    m_model->markFindings(findings, FindingMark::Status(status), reason.trimmed());
}

} // namespace rosarch
