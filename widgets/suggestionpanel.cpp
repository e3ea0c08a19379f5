#include "widgets/suggestionpanel.h"
#include "document/document.h"
#include "widgets/icons.h"
#include "widgets/suggestionfiltermodel.h"
#include "widgets/suggestionmodel.h"

#include <QAction>
#include <QComboBox>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeyEvent>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSplitter>
#include <QStackedWidget>
#include <QTextBrowser>
#include <QToolButton>
#include <QTreeView>
#include <QUrl>
#include <QVBoxLayout>

namespace rosarch {

namespace {

QToolButton *toolButton(QAction *action, QWidget *parent)
{
    auto *button = new QToolButton(parent);
    button->setDefaultAction(action);
    button->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    button->setAutoRaise(true);
    return button;
}

QString lineRange(const Evidence &e)
{
    return e.endLine > e.line ? QStringLiteral("%1–%2").arg(e.line).arg(e.endLine)
                              : QString::number(e.line);
}

} // namespace

SuggestionPanel::SuggestionPanel(QWidget *parent)
    : QWidget(parent), m_proxy(new SuggestionFilterModel(this)), m_countsLabel(new QLabel(this)),
      m_statusFilter(new QComboBox(this)), m_kindFilter(new QComboBox(this)),
      m_progressLabel(new QLabel(this)), m_llmLabel(new QLabel(this)),
      m_stack(new QStackedWidget(this)), m_emptyLabel(new QLabel(m_stack)),
      m_view(new QTreeView(m_stack)), m_acceptButton(new QPushButton(this)),
      m_rejectButton(new QPushButton(this)), m_acceptAllButton(new QPushButton(this)),
      m_details(new QTextBrowser(this)), m_splitter(new QSplitter(Qt::Vertical, this))
{
    createActions();

    // Header: how many of each status (the dock's title says "Suggestions"), and the filters.
    m_countsLabel->setTextFormat(Qt::PlainText);
    QFont bold = m_countsLabel->font();
    bold.setBold(true);
    m_countsLabel->setFont(bold);
    m_statusFilter->addItem(tr("All statuses"), -1);
    for (Suggestion::Status s :
         {Suggestion::Status::Pending, Suggestion::Status::Accepted, Suggestion::Status::Rejected})
        m_statusFilter->addItem(SuggestionModel::statusIcon(s), SuggestionModel::statusLabel(s),
                                int(s));
    m_statusFilter->setToolTip(tr("Show the suggestions of one status"));
    m_kindFilter->addItem(tr("All kinds"), -1);
    for (Suggestion::Kind k :
         {Suggestion::Kind::NodeDescription, Suggestion::Kind::SubsystemGrouping,
          Suggestion::Kind::NameResolution})
        m_kindFilter->addItem(SuggestionModel::kindPlural(k), int(k));
    m_kindFilter->setToolTip(tr("Show the suggestions of one kind"));
    connect(m_statusFilter, &QComboBox::currentIndexChanged, this, [this] {
        const int v = m_statusFilter->currentData().toInt();
        m_proxy->setStatusFilter(v < 0 ? std::nullopt : std::optional(Suggestion::Status(v)));
        updateEmptyState();
        updateButtons();
    });
    connect(m_kindFilter, &QComboBox::currentIndexChanged, this, [this] {
        const int v = m_kindFilter->currentData().toInt();
        m_proxy->setKindFilter(v < 0 ? std::nullopt : std::optional(Suggestion::Kind(v)));
        updateEmptyState();
        updateButtons();
    });

    auto *header = new QHBoxLayout;
    header->setContentsMargins(6, 4, 6, 0);
    header->addWidget(m_countsLabel, 1);
    header->addWidget(m_statusFilter);
    header->addWidget(m_kindFilter);

    // Tool row: run, cancel, settings, and what the run does.
    m_runButton = toolButton(m_runAction, this);
    m_cancelButton = toolButton(m_cancelAction, this);
    m_settingsButton = toolButton(m_settingsAction, this);
    m_progressLabel->setTextFormat(Qt::PlainText);
    m_llmLabel->setTextFormat(Qt::PlainText);
    m_llmLabel->setForegroundRole(QPalette::PlaceholderText);
    auto *tools = new QHBoxLayout;
    tools->setContentsMargins(2, 0, 6, 0);
    tools->setSpacing(2);
    tools->addWidget(m_runButton);
    tools->addWidget(m_cancelButton);
    tools->addWidget(m_settingsButton);
    tools->addSpacing(8);
    tools->addWidget(m_progressLabel, 1);
    tools->addWidget(m_llmLabel);

    // The list, or a word on how to get one.
    // The empty state sits on the list's background, in a readable column.
    auto *emptyPage = new QWidget(m_stack);
    emptyPage->setBackgroundRole(QPalette::Base);
    emptyPage->setAutoFillBackground(true);
    auto *emptyLayout = new QVBoxLayout(emptyPage);
    m_emptyLabel->setParent(emptyPage);
    m_emptyLabel->setAlignment(Qt::AlignCenter);
    m_emptyLabel->setWordWrap(true);
    m_emptyLabel->setForegroundRole(QPalette::PlaceholderText);
    m_emptyLabel->setMaximumWidth(520);
    emptyLayout->addWidget(m_emptyLabel, 0, Qt::AlignCenter);
    m_view->setModel(m_proxy);
    m_view->setRootIsDecorated(false);
    m_view->setUniformRowHeights(true);
    m_view->setAlternatingRowColors(true);
    m_view->setAllColumnsShowFocus(true);
    m_view->setSelectionMode(QAbstractItemView::SingleSelection);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setFrameShape(QFrame::NoFrame);
    m_view->setTextElideMode(Qt::ElideRight);
    m_view->installEventFilter(this);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex &current) { onCurrentChanged(current); });
    m_stack->addWidget(emptyPage);
    m_stack->addWidget(m_view);

    m_acceptButton->setToolTip(m_acceptAction->toolTip());
    m_rejectButton->setToolTip(m_rejectAction->toolTip());
    m_acceptAllButton->setToolTip(m_acceptAllAction->toolTip());
    for (QPushButton *b : {m_acceptButton, m_rejectButton, m_acceptAllButton})
        b->setAutoDefault(false);
    connect(m_acceptButton, &QPushButton::clicked, m_acceptAction, &QAction::trigger);
    connect(m_rejectButton, &QPushButton::clicked, m_rejectAction, &QAction::trigger);
    connect(m_acceptAllButton, &QPushButton::clicked, m_acceptAllAction, &QAction::trigger);
    auto *decide = new QHBoxLayout;
    decide->setContentsMargins(6, 4, 6, 4);
    decide->addWidget(m_acceptButton);
    decide->addWidget(m_rejectButton);
    decide->addStretch(1);
    decide->addWidget(m_acceptAllButton);

    auto *listArea = new QWidget(m_splitter);
    auto *listLayout = new QVBoxLayout(listArea);
    listLayout->setContentsMargins(0, 0, 0, 0);
    listLayout->setSpacing(0);
    listLayout->addWidget(m_stack, 1);
    listLayout->addLayout(decide);

    m_details->setOpenLinks(false);
    m_details->setFrameShape(QFrame::NoFrame);
    m_details->setPlaceholderText(tr("Select a suggestion to see its rationale and evidence."));
    connect(m_details, &QTextBrowser::anchorClicked, this, &SuggestionPanel::onAnchorClicked);
    m_splitter->addWidget(listArea);
    m_splitter->addWidget(m_details);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 2);
    m_splitter->setChildrenCollapsible(false);

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addLayout(header);
    layout->addLayout(tools);
    layout->addWidget(m_splitter, 1);

    setRunning(false);
    updateCounts();
    updateEmptyState();
    updateButtons();
}

void SuggestionPanel::createActions()
{
    m_runAction = new QAction(Icons::run(), tr("Run Suggestions"), this);
    m_runAction->setToolTip(tr("Propose node descriptions and subsystem groupings from the code "
                               "(and ask the LLM when one is configured)"));
    connect(m_runAction, &QAction::triggered, this, &SuggestionPanel::runRequested);
    m_cancelAction = new QAction(Icons::stop(), tr("Cancel"), this);
    m_cancelAction->setToolTip(tr("Stop asking the LLM; what arrived so far is kept"));
    connect(m_cancelAction, &QAction::triggered, this, &SuggestionPanel::cancelRequested);
    m_settingsAction = new QAction(tr("LLM Settings…"), this);
    m_settingsAction->setToolTip(tr("Endpoint, model and timeouts of the language model"));
    connect(m_settingsAction, &QAction::triggered, this, &SuggestionPanel::settingsRequested);

    m_acceptAction = new QAction(tr("Accept"), this);
    m_acceptAction->setToolTip(tr("Apply the proposed change (Enter); undo with Ctrl+Z"));
    connect(m_acceptAction, &QAction::triggered, this, &SuggestionPanel::acceptCurrent);
    m_rejectAction = new QAction(tr("Reject"), this);
    m_rejectAction->setToolTip(tr("Dismiss the proposal; it is not asked again (Delete)"));
    connect(m_rejectAction, &QAction::triggered, this, &SuggestionPanel::rejectCurrent);
    m_acceptAllAction = new QAction(tr("Accept All"), this);
    m_acceptAllAction->setToolTip(tr("Accept every pending suggestion of this kind, as one step "
                                     "on the undo stack"));
    connect(m_acceptAllAction, &QAction::triggered, this, &SuggestionPanel::acceptAllOfKind);
}

void SuggestionPanel::setModel(SuggestionModel *model)
{
    m_model = model;
    m_proxy->setSourceModel(model);
    QHeaderView *h = m_view->header();
    h->setStretchLastSection(false);
    h->setSectionResizeMode(QHeaderView::Interactive);
    h->setSectionResizeMode(SuggestionModel::ProposalColumn, QHeaderView::Stretch);
    m_view->setColumnWidth(SuggestionModel::KindColumn, 120);
    m_view->setColumnWidth(SuggestionModel::TargetColumn, 170);
    m_view->setColumnWidth(SuggestionModel::OriginColumn, 130);
    m_view->setColumnWidth(SuggestionModel::EvidenceColumn, 170);
    const auto refresh = [this] {
        updateCounts();
        updateEmptyState();
        updateButtons();
        updateDetails();
    };
    connect(model, &QAbstractItemModel::modelReset, this, refresh);
    connect(model, &QAbstractItemModel::dataChanged, this, refresh);
    refresh();
}

void SuggestionPanel::setRunning(bool running)
{
    m_running = running;
    m_runAction->setEnabled(!running);
    m_cancelAction->setEnabled(running);
    m_settingsAction->setEnabled(!running);
    updateEmptyState();
}

void SuggestionPanel::setProgressText(const QString &text)
{
    m_progressLabel->setText(text);
}

void SuggestionPanel::setLlmDescription(const QString &text)
{
    m_llmLabel->setText(text);
}

QString SuggestionPanel::currentSuggestionId() const
{
    const Suggestion *s = current();
    return s ? s->id : QString();
}

void SuggestionPanel::selectSuggestion(const QString &id)
{
    if (!m_model)
        return;
    const QModelIndex source = m_model->indexOf(id);
    if (!source.isValid())
        return;
    if (!m_proxy->mapFromSource(source).isValid()) {
        m_statusFilter->setCurrentIndex(0);
        m_kindFilter->setCurrentIndex(0);
    }
    const QModelIndex index = m_proxy->mapFromSource(source);
    m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect |
                                                         QItemSelectionModel::Rows);
    m_view->scrollTo(index);
}

const Suggestion *SuggestionPanel::current() const
{
    return m_model ? m_model->suggestion(m_proxy->mapToSource(m_view->currentIndex())) : nullptr;
}

bool SuggestionPanel::eventFilter(QObject *watched, QEvent *event)
{
    if (watched == m_view && event->type() == QEvent::KeyPress) {
        const auto *key = static_cast<QKeyEvent *>(event);
        if (key->modifiers() & ~Qt::KeypadModifier)
            return QWidget::eventFilter(watched, event);
        switch (key->key()) {
        case Qt::Key_Return:
        case Qt::Key_Enter:
            m_acceptAction->trigger();
            return true;
        case Qt::Key_Delete:
        case Qt::Key_Backspace:
            m_rejectAction->trigger();
            return true;
        default:
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void SuggestionPanel::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    // The status marks are drawn in palette colours.
    if (event->type() == QEvent::PaletteChange && m_statusFilter) {
        for (int i = 1; i < m_statusFilter->count(); ++i)
            m_statusFilter->setItemIcon(i, SuggestionModel::statusIcon(Suggestion::Status(
                                               m_statusFilter->itemData(i).toInt())));
    }
}

void SuggestionPanel::onCurrentChanged(const QModelIndex &)
{
    updateButtons();
    updateDetails();
    const Suggestion *s = current();
    Q_EMIT currentSuggestionChanged(s ? s->id : QString());
    if (!s)
        return;
    // Preview what the suggestion is about, then its evidence, so the source view ends on
    // the cited lines.
    switch (s->kind) {
    case Suggestion::Kind::NodeDescription:
        Q_EMIT nodeClassPreviewRequested(s->targetId);
        break;
    case Suggestion::Kind::SubsystemGrouping:
        Q_EMIT instancesPreviewRequested(s->memberIds);
        break;
    case Suggestion::Kind::NameResolution:
        if (const SuggestionItem *item = m_model->item(s->targetId)) {
            if (item->elementId.startsWith(QLatin1String("arc_")))
                Q_EMIT nodeClassPreviewRequested(item->elementId);
            else
                Q_EMIT instancesPreviewRequested({item->elementId});
        }
        break;
    }
    if (!s->evidence.isEmpty())
        Q_EMIT evidenceActivated(s->evidence.first().evidence);
}

void SuggestionPanel::onAnchorClicked(const QUrl &url)
{
    const Suggestion *s = current();
    bool ok = false;
    const int i = url.path().toInt(&ok);
    if (s && url.scheme() == QLatin1String("evidence") && ok && i >= 0 && i < s->evidence.size())
        Q_EMIT evidenceActivated(s->evidence[i].evidence);
}

void SuggestionPanel::acceptCurrent()
{
    const Suggestion *s = current();
    if (!s || s->status == Suggestion::Status::Accepted)
        return;
    const int row = m_view->currentIndex().row();
    Q_EMIT acceptRequested(s->id);
    advance(row);
}

void SuggestionPanel::rejectCurrent()
{
    const Suggestion *s = current();
    if (!s || s->status == Suggestion::Status::Rejected)
        return;
    const int row = m_view->currentIndex().row();
    Q_EMIT rejectRequested(s->id);
    advance(row);
}

void SuggestionPanel::acceptAllOfKind()
{
    if (const std::optional<Suggestion::Kind> kind = acceptAllKind())
        Q_EMIT acceptAllRequested(*kind);
}

void SuggestionPanel::advance(int fromRow)
{
    // Reviewing is a sequence of decisions: move on to the next one still open.
    const int rows = m_proxy->rowCount();
    if (rows == 0 || fromRow < 0)
        return;
    const Suggestion *s = current();
    if (s && s->status == Suggestion::Status::Pending)
        return; // the decision did not happen (or the row is still open)
    for (int step = 0; step < rows; ++step) {
        const QModelIndex index = m_proxy->index((fromRow + step) % rows, 0);
        if (index.data(SuggestionModel::StatusRole).toInt() == int(Suggestion::Status::Pending)) {
            m_view->selectionModel()->setCurrentIndex(index, QItemSelectionModel::ClearAndSelect |
                                                                 QItemSelectionModel::Rows);
            m_view->scrollTo(index);
            return;
        }
    }
}

void SuggestionPanel::updateCounts()
{
    if (!m_model || m_model->rowCount() == 0) {
        m_countsLabel->setText(tr("No suggestions"));
        return;
    }
    m_countsLabel->setText(tr("%1 pending · %2 accepted · %3 rejected")
                               .arg(m_model->count(Suggestion::Status::Pending))
                               .arg(m_model->count(Suggestion::Status::Accepted))
                               .arg(m_model->count(Suggestion::Status::Rejected)));
}

std::optional<Suggestion::Kind> SuggestionPanel::acceptAllKind() const
{
    if (const std::optional<Suggestion::Kind> k = m_proxy->kindFilter())
        return k;
    if (const Suggestion *s = current())
        return s->kind;
    return std::nullopt;
}

void SuggestionPanel::updateButtons()
{
    const Suggestion *s = current();
    m_acceptAction->setEnabled(s && s->status != Suggestion::Status::Accepted);
    m_rejectAction->setEnabled(s && s->status != Suggestion::Status::Rejected);
    const std::optional<Suggestion::Kind> kind = acceptAllKind();
    const int pending = kind && m_model ? m_model->count(Suggestion::Status::Pending, *kind) : 0;
    m_acceptAllAction->setEnabled(pending > 0);
    m_acceptAllAction->setText(
        kind ? tr("Accept All %1 (%2)").arg(SuggestionModel::kindPlural(*kind)).arg(pending)
             : tr("Accept All"));
    m_acceptButton->setText(m_acceptAction->text());
    m_rejectButton->setText(m_rejectAction->text());
    m_acceptAllButton->setText(m_acceptAllAction->text());
    m_acceptButton->setEnabled(m_acceptAction->isEnabled());
    m_rejectButton->setEnabled(m_rejectAction->isEnabled());
    m_acceptAllButton->setEnabled(m_acceptAllAction->isEnabled());
}

void SuggestionPanel::updateEmptyState()
{
    const bool empty = m_proxy->rowCount() == 0;
    if (empty) {
        if (m_running)
            m_emptyLabel->setText(tr("Looking for suggestions…"));
        else if (!m_model || m_model->rowCount() == 0)
            m_emptyLabel->setText(
                tr("No suggestions yet.\n\nRun Suggestions proposes node descriptions from "
                   "docstrings and comments and subsystem groupings from the topic graph; with "
                   "an LLM configured it also asks the model."));
        else
            m_emptyLabel->setText(tr("No suggestion matches the filter."));
    }
    m_stack->setCurrentIndex(empty ? 0 : 1);
}

void SuggestionPanel::updateDetails()
{
    const Suggestion *s = current();
    if (!s) {
        m_details->clear();
        return;
    }
    const auto esc = [](const QString &t) { return t.toHtmlEscaped(); };
    QString html = QStringLiteral("<p><b>%1</b> · %2 · <i>%3</i></p>")
                       .arg(esc(SuggestionModel::kindLabel(s->kind)), esc(m_model->targetText(*s)),
                            esc(SuggestionModel::statusLabel(s->status)));
    if (s->kind == Suggestion::Kind::SubsystemGrouping)
        html += QStringLiteral("<p>%1 <b>%2</b>: %3</p>")
                    .arg(esc(tr("Group")), esc(s->value), esc(m_model->proposalText(*s)));
    else
        html +=
            s->quoted
                ? QStringLiteral("<p>%1<br/><q><i>%2</i></q></p>")
                      .arg(esc(tr("Proposal, quoted from the code (the repository's "
                                  "words, not rosarch's):")),
                           esc(s->value))
                : QStringLiteral("<p>%1 <b>%2</b></p>").arg(esc(tr("Proposal:")), esc(s->value));
    if (!s->rationale.isEmpty())
        html += QStringLiteral("<p>%1</p>").arg(esc(s->rationale));
    if (!s->evidence.isEmpty()) {
        html += QStringLiteral("<p>%1<br/>").arg(esc(tr("Evidence:")));
        for (qsizetype i = 0; i < s->evidence.size(); ++i) {
            const Suggestion::Citation &c = s->evidence[i];
            html += QStringLiteral("&nbsp;&nbsp;<a href=\"evidence:%1\">%2:%3</a> “%4”<br/>")
                        .arg(i)
                        .arg(esc(c.evidence.file), lineRange(c.evidence), esc(c.quote));
        }
        html += QStringLiteral("</p>");
    }
    QString origin = SuggestionModel::originText(*s);
    if (!s->origin.prompt.isEmpty())
        origin += QStringLiteral(" · ") + s->origin.prompt;
    if (s->origin.timestamp.isValid())
        origin += QStringLiteral(" · ") +
                  QLocale().toString(s->origin.timestamp.toLocalTime(), QLocale::ShortFormat);
    html += QStringLiteral("<p><small>%1 %2</small></p>").arg(esc(tr("Origin:")), esc(origin));
    m_details->setHtml(html);
}

} // namespace rosarch
