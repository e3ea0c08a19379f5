#pragma once

#include "core/suggestion.h"
#include "document/projectsession.h"

#include <QUndoCommand>

namespace rosarch {

/// Undoable accept or reject of one suggestion: its status (and that of every suggestion
/// with the same subject and proposal), the stored decision and, for a node description,
/// the node's description. Undo restores the state captured when the command was made.
class DecideSuggestionCommand : public QUndoCommand
{
public:
    DecideSuggestionCommand(ProjectSession *session, const Suggestion &suggestion,
                            Suggestion::Status status, QUndoCommand *parent = nullptr);
    void undo() override;
    void redo() override;

private:
    ProjectSession *m_session;
    ProjectSession::DecisionSnapshot m_before;
    ProjectSession::DecisionSnapshot m_after;
};

} // namespace rosarch
