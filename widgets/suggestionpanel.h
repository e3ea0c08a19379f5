#pragma once

#include "core/evidence.h"
#include "core/suggestion.h"

#include <QModelIndex>
#include <QWidget>

#include <optional>

class QAction;
class QComboBox;
class QLabel;
class QPushButton;
class QSplitter;
class QStackedWidget;
class QTextBrowser;
class QToolButton;
class QTreeView;

namespace rosarch {

class SuggestionFilterModel;
class SuggestionModel;

/// The "Suggestions" panel: the suggestions of the last run, filterable by status and kind,
/// with accept / reject / accept all of a kind, the rationale and evidence of the current one,
/// and the run, cancel and LLM settings buttons. It shows and forwards intent only.
class SuggestionPanel : public QWidget
{
    Q_OBJECT
public:
    explicit SuggestionPanel(QWidget *parent = nullptr);

    void setModel(SuggestionModel *model);
    SuggestionModel *model() const { return m_model; }
    SuggestionFilterModel *filterModel() const { return m_proxy; }

    /// Shows a run in progress: Run disabled, Cancel enabled, the progress line visible.
    void setRunning(bool running);
    bool isRunning() const { return m_running; }
    /// The line beside the buttons: progress of a run, or what the last one used.
    void setProgressText(const QString &text);
    /// What the next run will use, e.g. "LLM off" or "LLM: gpt-4o-mini".
    void setLlmDescription(const QString &text);

    /// The id of the current suggestion ("" for none).
    QString currentSuggestionId() const;
    /// Makes suggestion `id` current, clearing filters that hide it.
    void selectSuggestion(const QString &id);

    // For tests and wiring.
    QTreeView *view() const { return m_view; }
    QComboBox *statusFilter() const { return m_statusFilter; }
    QComboBox *kindFilter() const { return m_kindFilter; }
    QLabel *countsLabel() const { return m_countsLabel; }
    QLabel *progressLabel() const { return m_progressLabel; }
    QTextBrowser *details() const { return m_details; }
    QAction *runAction() const { return m_runAction; }
    QAction *cancelAction() const { return m_cancelAction; }
    QAction *settingsAction() const { return m_settingsAction; }
    QAction *acceptAction() const { return m_acceptAction; }
    QAction *rejectAction() const { return m_rejectAction; }
    QAction *acceptAllAction() const { return m_acceptAllAction; }

Q_SIGNALS:
    void runRequested();
    void cancelRequested();
    void settingsRequested();
    void acceptRequested(const QString &id);
    void rejectRequested(const QString &id);
    void acceptAllRequested(rosarch::Suggestion::Kind kind);
    /// The current suggestion changed ("" for none).
    void currentSuggestionChanged(const QString &id);
    /// Show these lines in the source view (the current suggestion's evidence, or a citation
    /// clicked in the details).
    void evidenceActivated(const rosarch::Evidence &evidence);
    /// Show the node class (ARC id) a suggestion is about.
    void nodeClassPreviewRequested(const QString &arcId);
    /// Show the node instances a suggestion is about (a grouping's members).
    void instancesPreviewRequested(const QStringList &instanceIds);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;
    void changeEvent(QEvent *event) override;

private:
    void createActions();
    void onCurrentChanged(const QModelIndex &current);
    void onAnchorClicked(const QUrl &url);
    void acceptCurrent();
    void rejectCurrent();
    void acceptAllOfKind();
    /// After a decision: the next pending row from proxy row `fromRow` on becomes current.
    void advance(int fromRow);
    void updateCounts();
    void updateButtons();
    void updateDetails();
    void updateEmptyState();
    const Suggestion *current() const;
    /// The kind "Accept all" acts on: the kind filter, else the current suggestion's kind.
    std::optional<Suggestion::Kind> acceptAllKind() const;

    SuggestionModel *m_model = nullptr;
    SuggestionFilterModel *m_proxy;
    bool m_running = false;

    QLabel *m_countsLabel;
    QComboBox *m_statusFilter;
    QComboBox *m_kindFilter;
    QToolButton *m_runButton;
    QToolButton *m_cancelButton;
    QToolButton *m_settingsButton;
    QLabel *m_progressLabel;
    QLabel *m_llmLabel;
    QStackedWidget *m_stack;
    QLabel *m_emptyLabel;
    QTreeView *m_view;
    QPushButton *m_acceptButton;
    QPushButton *m_rejectButton;
    QPushButton *m_acceptAllButton;
    QTextBrowser *m_details;
    QSplitter *m_splitter;

    QAction *m_runAction;
    QAction *m_cancelAction;
    QAction *m_settingsAction;
    QAction *m_acceptAction;
    QAction *m_rejectAction;
    QAction *m_acceptAllAction;
};

} // namespace rosarch
