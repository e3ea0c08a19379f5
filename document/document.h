#pragma once

#include "acceptedmodel.h"
#include "atomicnodelist.h"
#include "launchanalyzer.h"
#include "launchdependencies.h"
#include "recovery.h"
#include "subsystemgroup.h"
#include "suggestiondecision.h"
#include "suggestionreport.h"

#include <QHash>
#include <QMap>
#include <QObject>
#include <QUndoStack>

#include <optional>

namespace rosarch {

/// The open project: the workspace, the recovered model and the undo stack for every
/// change a person makes to it. Views read from here; edits go through commands.
class Document : public QObject
{
    Q_OBJECT
public:
    explicit Document(QObject *parent = nullptr);

    QString workspaceRoot() const { return m_nodes.workspaceRoot; }
    const AtomicNodeList &atomicNodes() const { return m_nodes; }
    /// Stage 2's result; empty until stage 2 ran.
    const LaunchDependencies &launchDependencies() const { return m_launch; }
    /// Stage 3's result (composites per launch-file instance); empty until stage 3 ran.
    const Architecture &architecture() const { return m_architecture; }
    /// The root launch file and argument values stage 2 runs with (a person's choice).
    const LaunchOptions &launchOptions() const { return m_launchOptions; }
    QUndoStack *undoStack() { return &m_undoStack; }

    /// Replaces the whole model with the result of stages 1 and 2 (clears undo history).
    void setRecovery(Recovery recovery);
    /// Replaces the whole model with a stage 1 result and no launch dependencies.
    void setAtomicNodes(AtomicNodeList nodes);
    /// Replaces only the results of stages 2 and 3 (a re-run of stage 2); the atomic nodes
    /// and their undo history stay.
    void setLaunchDependencies(LaunchDependencies launch, Architecture architecture = {});
    /// Stores what the next stage 2 run uses; it does not run anything.
    void setLaunchOptions(const LaunchOptions &options);

    /// Pushes an undoable change of a node's description (a person's correction).
    void setNodeDescription(const QString &nodeId, const QString &description);

    // Suggestions (issue 5). Decisions are kept per workspace (DecisionStore) and applied
    // again whenever the model or the suggestions are replaced.

    /// The last suggestion run, each suggestion with its current status.
    const SuggestionReport &suggestionReport() const { return m_suggestionReport; }
    const QList<Suggestion> &suggestions() const { return m_suggestionReport.suggestions; }
    /// The suggestion with `id`, or null.
    const Suggestion *suggestion(const QString &id) const;
    /// Replaces the suggestions with a new run's. Suggestions whose subject and proposal were
    /// decided before get that status; accepted descriptions are applied again. Returns how
    /// many were already decided.
    int setSuggestions(SuggestionReport report);
    /// Pushes an undoable accept; false when there is no such suggestion or it is accepted.
    bool acceptSuggestion(const QString &id);
    /// Pushes an undoable reject; false when there is no such suggestion or it is rejected.
    bool rejectSuggestion(const QString &id);
    /// Accepts every pending suggestion of `kind` as one undo step; returns how many.
    int acceptAllSuggestions(Suggestion::Kind kind);
    /// Every decision of this workspace, by SuggestionDecision::key.
    const QMap<QString, SuggestionDecision> &decisions() const { return m_decisions; }
    /// Accepted subsystem groupings whose root and members exist in the current model.
    QList<SubsystemGroup> acceptedGroupings() const;
    /// Accepted values of unresolved items that exist in the current model: item id → value.
    QMap<QString, QString> acceptedNames() const;
    /// The model as accepted (AcceptedModel::apply of the recovery and the decisions): what the
    /// diagram draws and the exports write. Computed once per change of either.
    const Recovery &accepted() const;
    /// The decisions file of the workspace ("" without a workspace).
    QString decisionsPath() const;

    /// What a decision touches, captured for undo: the stored decision of one subject and
    /// proposal and, for a node description, the node's description.
    struct DecisionSnapshot
    {
        QString key;
        std::optional<SuggestionDecision> decision; ///< none = pending
        QString nodeId;                             ///< "" unless a node description
        QString description;
        bool operator==(const DecisionSnapshot &) const = default;
    };

Q_SIGNALS:
    /// The whole model is about to be replaced; item models begin their reset here.
    void modelAboutToBeReset();
    /// The whole model was replaced (a stage finished).
    void modelReset();
    /// Only the launch dependencies are about to be replaced (stage 2 re-run).
    void launchDependenciesAboutToBeReset();
    /// Only the launch dependencies were replaced (stage 2 re-run).
    void launchDependenciesReset();
    /// The launch options changed.
    void launchOptionsChanged(const rosarch::LaunchOptions &options);
    /// One node changed (an edit, its undo or redo).
    void nodeChanged(const QString &nodeId);
    /// The suggestion list is about to be replaced (a suggestion run, or the model changed).
    void suggestionsAboutToBeReset();
    /// The suggestion list was replaced.
    void suggestionsReset();
    /// One suggestion's status changed (a decision, its undo or redo).
    void suggestionChanged(const QString &id);
    /// The accepted decisions changed (groupings, names, descriptions).
    void decisionsChanged();
    /// The decisions could not be written; `message` says where and why.
    void decisionsSaveFailed(const QString &message);

private:
    friend class SetNodeDescriptionCommand;
    friend class DecideSuggestionCommand;
    void applyNodeDescription(const QString &nodeId, const QString &description);

    DecisionSnapshot snapshot(const Suggestion &suggestion) const;
    DecisionSnapshot decided(const Suggestion &suggestion, Suggestion::Status status) const;
    void restore(const DecisionSnapshot &snapshot);
    /// Reads the workspace's decisions and applies the accepted descriptions (no signals).
    void loadDecisions();
    void saveDecisions();
    void clearSuggestions();

    AtomicNodeList m_nodes;
    LaunchDependencies m_launch;
    Architecture m_architecture;
    LaunchOptions m_launchOptions;
    SuggestionReport m_suggestionReport;
    QMap<QString, SuggestionDecision> m_decisions;
    QHash<QString, QString> m_analysisDescriptions; ///< as stage 1 found them, by node id
    mutable std::optional<Recovery> m_accepted;     ///< accepted(), until the next change
    QUndoStack m_undoStack;
};

} // namespace rosarch
