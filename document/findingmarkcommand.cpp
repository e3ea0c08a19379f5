#include "document/findingmarkcommand.h"
#include "document/projectsession.h"

namespace rosarch {

FindingMarkCommand::FindingMarkCommand(ProjectSession *session, Marks before, Marks after,
                                       const QString &text)
    : m_session(session), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void FindingMarkCommand::undo()
{
    m_session->replaceFindingMarks(m_before);
}

void FindingMarkCommand::redo()
{
    m_session->replaceFindingMarks(m_after);
}

} // namespace rosarch
