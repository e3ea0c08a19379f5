#include "document/decidesuggestioncommand.h"

#include <QCoreApplication>

namespace rosarch {

DecideSuggestionCommand::DecideSuggestionCommand(Document *document, const Suggestion &suggestion,
                                                 Suggestion::Status status, QUndoCommand *parent)
    : QUndoCommand(parent), m_document(document), m_before(document->snapshot(suggestion)),
      m_after(document->decided(suggestion, status))
{
    setText(status == Suggestion::Status::Accepted
                ? QCoreApplication::translate("rosarch::Document", "Accept suggestion")
                : QCoreApplication::translate("rosarch::Document", "Reject suggestion"));
}

void DecideSuggestionCommand::undo()
{
    m_document->restore(m_before);
}

void DecideSuggestionCommand::redo()
{
    m_document->restore(m_after);
}

} // namespace rosarch
