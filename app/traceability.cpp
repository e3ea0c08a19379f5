#include "app/traceability.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/evidencelines.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"

#include <QScopedValueRollback>
#include <QTreeView>

namespace rosarch {

Traceability::Traceability(AtomicNodeModel *nodeModel, AtomicNodePanel *nodePanel,
                           LaunchTreeModel *launchModel, LaunchTreePanel *launchPanel,
                           SourceView *sourceView, QObject *parent)
    : QObject(parent), m_nodeModel(nodeModel), m_nodePanel(nodePanel), m_launchModel(launchModel),
      m_launchPanel(launchPanel), m_sourceView(sourceView)
{
    connect(m_nodePanel, &AtomicNodePanel::currentSourceIndexChanged, this,
            &Traceability::onNodeSelected);
    connect(m_launchPanel, &LaunchTreePanel::currentSourceIndexChanged, this,
            &Traceability::onLaunchItemSelected);
    connect(m_launchPanel, &LaunchTreePanel::classRequested, this, &Traceability::goToClass);
    connect(m_sourceView, &SourceView::cursorLineChanged, this, &Traceability::onSourceLineChanged);
}

void Traceability::selectNode(const QString &nodeId, const QString &portId)
{
    const QModelIndex index =
        portId.isEmpty() ? m_nodeModel->nodeIndex(nodeId) : m_nodeModel->portIndex(nodeId, portId);
    const QScopedValueRollback guard(m_selecting, true);
    if (index.isValid())
        m_nodePanel->selectSourceIndex(index);
}

void Traceability::selectLaunchItem(const QString &instanceId)
{
    QModelIndex index = m_launchModel->nodeIndex(instanceId);
    if (!index.isValid())
        index = m_launchModel->launchFileIndex(instanceId);
    if (index.isValid())
        m_launchPanel->selectSourceIndex(index);
}

void Traceability::goToClass(const QString &classId)
{
    const QModelIndex index = m_nodeModel->nodeIndex(classId);
    if (!index.isValid())
        return;
    if (m_nodePanel->currentSourceIndex() == index) // already there: show it again
        onNodeSelected(index);
    else
        m_nodePanel->selectSourceIndex(index);
    m_nodePanel->treeView()->setFocus(Qt::OtherFocusReason);
}

void Traceability::showEvidence(const Evidence &evidence)
{
    if (!m_sourceView->showEvidence(evidence))
        Q_EMIT evidenceUnavailable(evidence);
}

QString Traceability::currentNodeId() const
{
    return m_nodePanel->currentSourceIndex().data(AtomicNodeModel::NodeIdRole).toString();
}

QString Traceability::currentPortId() const
{
    return m_nodePanel->currentSourceIndex().data(AtomicNodeModel::PortIdRole).toString();
}

QString Traceability::currentLaunchId() const
{
    return m_launchPanel->currentSourceIndex().data(LaunchTreeModel::InstanceIdRole).toString();
}

void Traceability::onNodeSelected(const QModelIndex &sourceIndex)
{
    if (m_syncing)
        return;
    const Evidence evidence = m_nodeModel->evidence(sourceIndex);
    if (evidence.isValid())
        showEvidence(evidence);
    const QString portId = sourceIndex.data(AtomicNodeModel::PortIdRole).toString();
    if (!portId.isEmpty() && !m_selecting)
        Q_EMIT portSelected(sourceIndex.data(AtomicNodeModel::NodeIdRole).toString(), portId);
}

void Traceability::onLaunchItemSelected(const QModelIndex &sourceIndex)
{
    if (m_syncing)
        return;
    const Evidence evidence = m_launchModel->evidence(sourceIndex);
    if (evidence.isValid())
        showEvidence(evidence);
    followClass(sourceIndex);
}

void Traceability::followClass(const QModelIndex &launchIndex)
{
    const QString classId = launchIndex.data(LaunchTreeModel::ClassIdRole).toString();
    const QModelIndex cls = classId.isEmpty() ? QModelIndex() : m_nodeModel->nodeIndex(classId);
    if (!cls.isValid() || m_nodePanel->currentSourceIndex() == cls)
        return;
    // The atomic tree follows; the source keeps showing the launch line.
    const QScopedValueRollback guard(m_syncing, true);
    m_nodePanel->selectSourceIndex(cls);
}

void Traceability::onSourceLineChanged(const QString &file, int line)
{
    const QScopedValueRollback guard(m_syncing, true);
    const QModelIndex launchIndex =
        m_launchModel->indexAt(file, line, m_launchPanel->currentSourceIndex());
    if (launchIndex.isValid()) {
        if (m_launchPanel->currentSourceIndex() != launchIndex)
            m_launchPanel->selectSourceIndex(launchIndex);
        const QString classId = launchIndex.data(LaunchTreeModel::ClassIdRole).toString();
        const QModelIndex cls = classId.isEmpty() ? QModelIndex() : m_nodeModel->nodeIndex(classId);
        if (cls.isValid() && m_nodePanel->currentSourceIndex() != cls)
            m_nodePanel->selectSourceIndex(cls);
    }
    const QModelIndex nodeIndex = preferCurrentClass(m_nodeModel->indexAt(file, line), file, line);
    if (nodeIndex.isValid())
        m_nodePanel->selectSourceIndex(nodeIndex);
}

QModelIndex Traceability::preferCurrentClass(const QModelIndex &found, const QString &file,
                                             int line) const
{
    // A helper's line (a function several classes call to make a port) is the evidence of a
    // port of each of them, all as narrow: the class the person came from keeps it, rather
    // than whichever class comes first.
    const AtomicNode *current = m_nodeModel->node(m_nodePanel->currentSourceIndex());
    const AtomicNode *other = m_nodeModel->node(found);
    int foundSpan = 0;
    if (!current || !other || current->id == other->id ||
        !coversLine(m_nodeModel->evidence(found), file, line, &foundSpan))
        return found;
    int span = 0;
    for (const Port &p : current->ports)
        if (coversLine(p.evidence, file, line, &span) && span <= foundSpan)
            return m_nodeModel->portIndex(current->id, p.id);
    if (coversLine(current->evidence, file, line, &span) && span <= foundSpan)
        return m_nodeModel->nodeIndex(current->id);
    return found;
}

} // namespace rosarch
