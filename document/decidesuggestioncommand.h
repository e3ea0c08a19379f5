#pragma once

#include "core/suggestion.h"
#include "document/document.h"

#include <QUndoCommand>

namespace rosarch {

/// Undoable accept or reject of one suggestion: its status (and that of every suggestion
/// with the same subject and proposal), the stored decision and, for a node description,
/// the node's description. Undo restores the state captured when the command was made.
class DecideSuggestionCommand : public QUndoCommand
{
public:
    DecideSuggestionCommand(Document *document, const Suggestion &suggestion,
                            Suggestion::Status status, QUndoCommand *parent = nullptr);
    void undo() override;
    void redo() override;

private:
    Document *m_document;
    Document::DecisionSnapshot m_before;
    Document::DecisionSnapshot m_after;
};

} // namespace rosarch
