#include "setnodedescriptioncommand.h"
#include "document.h"

#include <QCoreApplication>

namespace rosarch {

SetNodeDescriptionCommand::SetNodeDescriptionCommand(Document *document, QString nodeId,
                                                     QString before, QString after)
    : m_document(document), m_nodeId(std::move(nodeId)), m_before(std::move(before)),
      m_after(std::move(after))
{
    setText(QCoreApplication::translate("rosarch::Document", "Edit description"));
}

void SetNodeDescriptionCommand::undo()
{
    m_document->applyNodeDescription(m_nodeId, m_before);
}

void SetNodeDescriptionCommand::redo()
{
    m_document->applyNodeDescription(m_nodeId, m_after);
}

} // namespace rosarch
