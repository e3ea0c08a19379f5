#include "document/findingmarkcommand.h"
#include "document/document.h"

namespace rosarch {

FindingMarkCommand::FindingMarkCommand(Document *document, Marks before, Marks after,
                                       const QString &text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void FindingMarkCommand::undo()
{
    m_document->replaceFindingMarks(m_before);
}

void FindingMarkCommand::redo()
{
    m_document->replaceFindingMarks(m_after);
}

} // namespace rosarch
