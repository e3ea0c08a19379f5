#pragma once

#include "project/correction.h"

#include <QUndoCommand>

namespace rosarch {

class Document;

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
    CorrectionCommand(Document *document, Action action, Correction correction, int index,
                      QUndoCommand *parent = nullptr);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    Action m_action;
    Correction m_correction;
    int m_index; ///< where it is (or goes) in the project's list
};

} // namespace rosarch
