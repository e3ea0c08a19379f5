#include "app/parametercontroller.h"

#include "app/traceability.h"
#include "core/parameterview.h"
#include "core/rosnames.h"
#include "document/document.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/parameterpanel.h"
#include "widgets/parametertablemodel.h"

namespace rosarch {

ParameterController::ParameterController(Document *document, AtomicNodeModel *nodeModel,
                                         AtomicNodePanel *nodePanel, LaunchTreeModel *launchModel,
                                         LaunchTreePanel *launchPanel, ParameterPanel *panel,
                                         Traceability *traceability, QObject *parent)
    : QObject(parent), m_document(document), m_nodeModel(nodeModel), m_launchModel(launchModel),
      m_panel(panel)
{
    connect(launchPanel, &FilteredTreePanel::currentSourceIndexChanged, this,
            &ParameterController::showInstance);
    connect(nodePanel, &FilteredTreePanel::currentSourceIndexChanged, this,
            &ParameterController::showClass);
    connect(panel, &ParameterPanel::evidenceRequested, traceability,
            [traceability](const QString &file, int line) {
                traceability->showEvidence({file, line, 1, line, 1});
            });
}

void ParameterController::showInstance(const QModelIndex &sourceIndex)
{
    const NodeInstance *n = m_launchModel->node(sourceIndex);
    if (!n)
        return; // a launch file or an argument: the panel keeps what it shows
    const ParameterView view(m_document->atomicNodes());
    const QString name = RosNames::fullyQualified(n->nameSpace, n->nodeName);
    const QString title =
        n->className.isEmpty() ? name : QStringLiteral("%1 (%2)").arg(name, n->className);
    m_panel->showParameters(title, view.of(*n), true);
}

void ParameterController::showClass(const QModelIndex &sourceIndex)
{
    if (m_nodeModel->kind(sourceIndex) != AtomicNodeModel::ItemKind::Node)
        return;
    const AtomicNode *node = m_nodeModel->node(sourceIndex);
    if (!node)
        return;
    QString title = node->className;
    if (node->acceptsUndeclared)
        title += tr(" (takes any parameter)");
    m_panel->showParameters(title, ParameterTableModel::declaredOnly(node->parameters), false);
}

} // namespace rosarch
