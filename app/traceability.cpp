#include "app/traceability.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/evidencelines.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/sourceview.h"

#include <Qsci/qsciscintilla.h>

#include <QMenu>
#include <QScopedValueRollback>
#include <QTreeView>

#include <algorithm>

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
    const QModelIndexList users = usersOfLine(file, line);
    if (users.size() == 1) {
        m_nodePanel->selectSourceIndex(users.first());
        return;
    }
    // A helper's line (a function several classes call to make a port) is the evidence of a
    // port of each of them, all as narrow: the class the person came from keeps it; else the
    // person says which class they are after.
    const AtomicNode *current = m_nodeModel->node(m_nodePanel->currentSourceIndex());
    for (const QModelIndex &user : users)
        if (current && m_nodeModel->node(user)->id == current->id) {
            if (m_nodePanel->currentSourceIndex() != user)
                m_nodePanel->selectSourceIndex(user);
            return;
        }
    // A person reading with the arrow keys is not stopped by a menu that takes the keys; a
    // click on the line asks.
    if (!users.isEmpty() && !m_sourceView->movedByKey())
        offerClassChoice(users);
}

QModelIndexList Traceability::usersOfLine(const QString &file, int line) const
{
    const QModelIndex innermost = m_nodeModel->indexAt(file, line);
    int narrowest = 0;
    if (!innermost.isValid() ||
        !coversLine(m_nodeModel->evidence(innermost), file, line, &narrowest))
        return {};
    QList<std::pair<QString, QModelIndex>> users; // by "package/Class"
    for (int p = 0; p < m_nodeModel->rowCount(); ++p) {
        const QModelIndex package = m_nodeModel->index(p, 0);
        for (int n = 0; n < m_nodeModel->rowCount(package); ++n) {
            const AtomicNode *node = m_nodeModel->node(m_nodeModel->index(n, 0, package));
            if (!node)
                continue;
            QModelIndex use;
            int span = 0;
            for (const Port &port : node->ports)
                if (!use.isValid() && coversLine(port.evidence, file, line, &span) &&
                    span <= narrowest)
                    use = m_nodeModel->portIndex(node->id, port.id);
            if (!use.isValid() && coversLine(node->evidence, file, line, &span) &&
                span <= narrowest)
                use = m_nodeModel->nodeIndex(node->id);
            if (use.isValid())
                users.append({node->packageName + u'/' + node->className, use});
        }
    }
    std::sort(users.begin(), users.end(),
              [](const auto &a, const auto &b) { return a.first < b.first; });
    QModelIndexList indexes;
    for (const auto &user : users)
        indexes.append(user.second);
    return indexes;
}

void Traceability::offerClassChoice(const QModelIndexList &users)
{
    if (m_choice)
        m_choice->close();
    auto *menu = new QMenu(m_sourceView);
    menu->setObjectName(QStringLiteral("classChoiceMenu"));
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->setToolTipsVisible(true);
    menu->addSection(tr("Used by %n classes", nullptr, int(users.size())));
    for (const QModelIndex &user : users) {
        const AtomicNode *node = m_nodeModel->node(user);
        QAction *go = menu->addAction(node->packageName + u'/' + node->className);
        go->setToolTip(tr("Go to %1 in the node list").arg(node->className));
        const QPersistentModelIndex target(user);
        connect(go, &QAction::triggered, this, [this, target, menu] {
            menu->close();
            if (!target.isValid())
                return;
            // The source stays on the line the person chose the class from.
            const QScopedValueRollback guard(m_syncing, true);
            m_nodePanel->selectSourceIndex(target);
        });
    }
    m_choice = menu;
    // Under the cursor's line, where the person is looking.
    QsciScintilla *editor = m_sourceView->editor();
    const long position = editor->SendScintilla(QsciScintilla::SCI_GETCURRENTPOS);
    const QPoint at(
        int(editor->SendScintilla(QsciScintilla::SCI_POINTXFROMPOSITION, 0UL, position)),
        int(editor->SendScintilla(QsciScintilla::SCI_POINTYFROMPOSITION, 0UL, position) +
            editor->SendScintilla(QsciScintilla::SCI_TEXTHEIGHT, 0UL)));
    menu->popup(editor->viewport()->mapToGlobal(at));
}

} // namespace rosarch
