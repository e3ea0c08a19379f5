#pragma once

#include "atomicnodelist.h"
#include "launchanalyzer.h"
#include "launchdependencies.h"
#include "recovery.h"

#include <QObject>
#include <QUndoStack>

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

private:
    friend class SetNodeDescriptionCommand;
    void applyNodeDescription(const QString &nodeId, const QString &description);

    AtomicNodeList m_nodes;
    LaunchDependencies m_launch;
    Architecture m_architecture;
    LaunchOptions m_launchOptions;
    QUndoStack m_undoStack;
};

} // namespace rosarch
