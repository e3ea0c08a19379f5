#include "document/decidesuggestioncommand.h"

#include <QCoreApplication>

namespace rosarch {

DecideSuggestionCommand::DecideSuggestionCommand(ProjectSession *session,
                                                 const Suggestion &suggestion,
                                                 Suggestion::Status status, QUndoCommand *parent)
    : QUndoCommand(parent), m_session(session), m_before(session->snapshot(suggestion)),
      m_after(session->decided(suggestion, status))
{
    setText(status == Suggestion::Status::Accepted
                ? QCoreApplication::translate("rosarch::Document", "Accept suggestion")
                : QCoreApplication::translate("rosarch::Document", "Reject suggestion"));
}

void DecideSuggestionCommand::undo()
{
    m_session->restore(m_before);
}

void DecideSuggestionCommand::redo()
{
    m_session->restore(m_after);
}

} // namespace rosarch
