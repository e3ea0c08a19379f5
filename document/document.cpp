#include "document.h"
#include "setnodedescriptioncommand.h"

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent) {}

void Document::setAtomicNodes(AtomicNodeList nodes)
{
    Q_EMIT modelAboutToBeReset();
    m_undoStack.clear();
    m_nodes = std::move(nodes);
    Q_EMIT modelReset();
}

void Document::setNodeDescription(const QString &nodeId, const QString &description)
{
    const AtomicNode *node = m_nodes.node(nodeId);
    if (!node || node->description == description)
        return;
    m_undoStack.push(new SetNodeDescriptionCommand(this, nodeId, node->description, description));
}

void Document::applyNodeDescription(const QString &nodeId, const QString &description)
{
    for (AtomicNode &n : m_nodes.nodes) {
        if (n.id == nodeId) {
            n.description = description;
            Q_EMIT nodeChanged(nodeId);
            return;
        }
    }
}

} // namespace rosarch
