#pragma once

#include "project/correction.h"

#include <QUndoCommand>

namespace rosarch {

class ProjectSession;

/// Undoable addition or removal of one correction (blueprint §5). Removing a correction
/// reverts what it changed; undoing the removal puts it back where it was in the list.
class CorrectionCommand : public QUndoCommand
{
public:
    enum class Action
    {
        Add,
        Remove
    };
    CorrectionCommand(ProjectSession *session, Action action, Correction correction, int index,
                      QUndoCommand *parent = nullptr);
    void undo() override;
    void redo() override;

private:
    ProjectSession *m_session;
    Action m_action;
    Correction m_correction;
    int m_index; ///< where it is (or goes) in the project's list
};

} // namespace rosarch
