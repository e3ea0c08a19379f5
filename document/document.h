#pragma once

#include "atomicnodelist.h"

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
    QUndoStack *undoStack() { return &m_undoStack; }

    /// Replaces the recovered model with a new stage result (clears undo history).
    void setAtomicNodes(AtomicNodeList nodes);

    /// Pushes an undoable change of a node's description (a person's correction).
    void setNodeDescription(const QString &nodeId, const QString &description);

Q_SIGNALS:
    /// The whole model is about to be replaced; item models begin their reset here.
    void modelAboutToBeReset();
    /// The whole model was replaced (a stage finished).
    void modelReset();
    /// One node changed (an edit, its undo or redo).
    void nodeChanged(const QString &nodeId);

private:
    friend class SetNodeDescriptionCommand;
    void applyNodeDescription(const QString &nodeId, const QString &description);

    AtomicNodeList m_nodes;
    QUndoStack m_undoStack;
};

} // namespace rosarch
