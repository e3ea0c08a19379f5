#include "document.h"
#include "setnodedescriptioncommand.h"

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent) {}

void Document::setRecovery(Recovery recovery)
{
    Q_EMIT modelAboutToBeReset();
    m_undoStack.clear();
    m_nodes = std::move(recovery.nodes);
    m_launch = std::move(recovery.launch);
    m_architecture = std::move(recovery.architecture);
    Q_EMIT modelReset();
}

void Document::setAtomicNodes(AtomicNodeList nodes)
{
    setRecovery({std::move(nodes), {}});
}

void Document::setLaunchDependencies(LaunchDependencies launch, Architecture architecture)
{
    Q_EMIT launchDependenciesAboutToBeReset();
    m_launch = std::move(launch);
    m_architecture = std::move(architecture);
    Q_EMIT launchDependenciesReset();
}

void Document::setLaunchOptions(const LaunchOptions &options)
{
    if (options == m_launchOptions)
        return;
    m_launchOptions = options;
    Q_EMIT launchOptionsChanged(m_launchOptions);
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
