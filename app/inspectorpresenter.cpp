#include "app/inspectorpresenter.h"
#include "app/correctionlookup.h"
#include "app/correctiontargets.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "document/nodedescription.h"
#include "jobs/stallprobe.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"

#include <QAction>

#include <algorithm>

namespace rosarch {

namespace {

using Kind = CorrectionElement::Kind;
using namespace CorrectionLookup;

} // namespace

InspectorPresenter::InspectorPresenter(Document *document, CorrectionTargets *targets,
                                       AtomicNodePanel *nodePanel, LaunchTreePanel *launchPanel,
                                       DiagramPanel *diagramPanel, InspectorPanel *inspector,
                                       QObject *parent)
    : QObject(parent), m_document(document), m_targets(targets), m_nodePanel(nodePanel),
      m_launchPanel(launchPanel), m_diagramPanel(diagramPanel), m_inspector(inspector)
{
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        const StallScope scope("InspectorPresenter (document changed)");
        if (change.has(DocumentChange::Model))
            m_current = {};
        refreshInspector();
    });
    connect(document->session(), &ProjectSession::keysMade, this, [this] {
        if (m_current.kind != Kind::None)
            refreshInspector(); // its key, shown as being worked out until now
    });
    connect(nodePanel, &FilteredTreePanel::currentSourceIndexChanged, this,
            [this](const QModelIndex &index) { setCurrent(nodeElement(index)); });
    connect(launchPanel, &FilteredTreePanel::currentSourceIndexChanged, this,
            [this](const QModelIndex &index) { setCurrent(launchElement(index)); });
    connect(diagramPanel, &DiagramPanel::elementActivated, this,
            [this](const QString &key) { setCurrent(diagramElement(key)); });
}

void InspectorPresenter::setActions(Actions actions)
{
    m_actions = std::move(actions);
}

void InspectorPresenter::setCurrent(const CorrectionElement &element)
{
    if (element == m_current)
        return;
    m_current = element;
    refreshInspector();
}

void InspectorPresenter::refreshInspector()
{
    if (!m_inspector)
        return;
    m_inspector->setElement(describe(m_current),
                            m_actions ? m_actions(m_current, m_inspector) : QList<QAction *>());
}

CorrectionElement InspectorPresenter::nodeElement(const QModelIndex &index) const
{
    const AtomicNodeModel *model = m_nodePanel->model();
    if (!model)
        return {};
    switch (model->kind(index)) {
    case AtomicNodeModel::ItemKind::Node:
        return {Kind::Class, model->elementId(index), {}, {}};
    case AtomicNodeModel::ItemKind::Port:
        return {Kind::Port, model->elementId(index), {}, {}};
    default:
        return {};
    }
}

CorrectionElement InspectorPresenter::launchElement(const QModelIndex &index) const
{
    const LaunchTreeModel *model = m_launchPanel->model();
    if (!model)
        return {};
    const auto rootOf = [this](QString lf) {
        const LaunchDependencies &launch = m_document->accepted().launch;
        for (const LaunchFileInstance *i = launch.instance(lf); i && !i->parentId.isEmpty();
             i = launch.instance(i->parentId))
            lf = i->parentId;
        return lf;
    };
    switch (model->kind(index)) {
    case LaunchTreeModel::ItemKind::Node:
        if (const NodeInstance *n = model->node(index))
            return {Kind::Instance, n->id, {}, rootOf(n->launchFileId)};
        return {};
    case LaunchTreeModel::ItemKind::LaunchFile:
        if (const LaunchFileInstance *lf = model->launchFile(index))
            return {Kind::LaunchFile, lf->id, {}, rootOf(lf->id)};
        return {};
    default:
        return {};
    }
}

CorrectionElement InspectorPresenter::diagramElement(const QString &key) const
{
    const Architecture &architecture = m_diagramPanel->architecture();
    const Composite *c = architecture.composite(m_diagramPanel->currentComposite());
    if (!c)
        return {};
    QString root = c->instanceId;
    for (const Composite *p = c; p && !p->parentId.isEmpty(); p = architecture.composite(root))
        root = p->parentId;
    const DiagramKey k = DiagramKey::parse(key);
    switch (k.kind) {
    case DiagramKey::Kind::Part:
        if (const RosNodePart *part = c->part(k.id))
            return {part->kind == RosNodePart::Kind::Node ? Kind::Instance : Kind::LaunchFile,
                    part->instanceId,
                    {},
                    root};
        return {};
    case DiagramKey::Kind::Port:
        if (const RosNodePart *part = c->part(k.id);
            part && part->kind == RosNodePart::Kind::Node && !part->typeId.isEmpty())
            return {Kind::Port, part->typeId + u'/' + k.portId, {}, {}};
        return {};
    case DiagramKey::Kind::Channel:
        if (const Channel *ch = c->channel(k.id))
            return {Kind::Channel, channelFamily(ch->kind) + u':' + ch->name, {}, {}};
        return {};
    case DiagramKey::Kind::Connection: {
        if (k.index() < 0 || k.index() >= c->connections.size())
            return {};
        const Connection &w = c->connections[k.index()];
        const RosNodePart *part = c->part(w.partId);
        if (!part || part->kind != RosNodePart::Kind::Node)
            return {};
        return {Kind::Connection, part->instanceId, part->typeId + u'/' + w.portId, root};
    }
    default:
        return {};
    }
}

void InspectorPresenter::describeClass(InspectorInfo &info, const QString &classId) const
{
    // one query for every view that shows a description (node list, inspector, diagram)
    const NodeDescription d = NodeDescription::of(*m_document, classId);
    info.describable = true;
    info.description = d.text;
    info.descriptionSource = d.sourceText();
}

InspectorInfo InspectorPresenter::describe(const CorrectionElement &e)
{
    InspectorInfo info;
    const Recovery &now = m_document->accepted();
    Marks marks;
    switch (e.kind) {
    case Kind::None:
        return info;
    case Kind::Class: {
        const AtomicNode *n = now.nodes.node(e.id);
        if (!n)
            n = m_document->atomicNodes().node(e.id);
        if (!n)
            return {};
        info.kind = n->isPlugin() ? tr("Plugin class") : tr("Node class");
        info.type = n->packageName;
        marks = n->marks;
        describeClass(info, e.id);
        break;
    }
    case Kind::Port: {
        const Port *p = findPort(now.nodes, e.id);
        if (!p)
            p = findPort(m_document->atomicNodes(), e.id);
        if (!p)
            return {};
        info.kind = tr("Port (%1)").arg(portKindName(p->kind));
        info.type = p->type;
        marks = p->marks;
        break;
    }
    case Kind::Instance:
    case Kind::Connection: {
        const NodeInstance *n = now.launch.node(e.id);
        if (!n)
            n = m_document->launchDependencies().node(e.id);
        if (!n)
            return {};
        info.kind = e.kind == Kind::Instance ? tr("Node instance") : tr("Connection");
        info.type = n->className.isEmpty() ? n->execName : n->className;
        if (e.kind == Kind::Instance)
            describeClass(info, n->classId);
        if (e.kind == Kind::Connection)
            if (const Port *p = findPort(now.nodes, e.port))
                info.type = tr("%1 %2 [%3]").arg(portKindName(p->kind), portName(*p), p->type);
        marks = n->marks;
        break;
    }
    case Kind::LaunchFile: {
        const LaunchFileInstance *lf = now.launch.instance(e.id);
        if (!lf)
            return {};
        info.kind = lf->format == QLatin1String("executable")
                        ? tr("Executable (nodes built in code)")
                        : tr("Launch file");
        info.type = lf->file;
        break;
    }
    case Kind::Channel: {
        const Channel *ch = findChannel(now.architecture, e.id);
        info.kind = StableKeys::family(e.id) == QLatin1String("topic")     ? tr("Topic")
                    : StableKeys::family(e.id) == QLatin1String("service") ? tr("Service")
                                                                           : tr("Action");
        info.type = ch ? ch->type : QString();
        if (ch)
            marks = ch->marks;
        break;
    }
    }
    info.name = m_targets->nameOf(e);
    if (!m_targets->keysAtHand(e.id)) {
        info.key = tr("(being worked out\u2026)"); // shown when the keys are made
    } else {
        info.key = m_targets->keyOf(e.kind == Kind::Connection ? e.port : e.id);
        if (e.kind == Kind::Connection)
            info.key = m_targets->keyOf(e.id) + QStringLiteral(" \u00b7 ") + info.key;
    }
    QStringList by;
    const QList<Correction> touching = m_targets->index().of(e.id);
    for (const Correction &c : touching)
        if (c.kind != Correction::Kind::Review)
            by.append(c.id);
    if (const QString removed = m_targets->index().removedBy(e.id); !removed.isEmpty())
        info.provenance = tr("removed by %1").arg(removed);
    else if (!by.isEmpty())
        info.provenance = tr("corrected by %1").arg(by.join(QStringLiteral(", ")));
    else if (marks.provenance == Provenance::Suggested)
        info.provenance = tr("suggested (an accepted suggestion)");
    else if (marks.provenance == Provenance::Corrected)
        info.provenance = tr("corrected");
    else
        info.provenance = tr("recovered by analysis");
    info.reviewed =
        marks.reviewed || std::any_of(touching.cbegin(), touching.cend(), [](const Correction &c) {
            return c.kind == Correction::Kind::Review;
        });
    info.corrections = m_targets->index().summary(e.id);
    return info;
}

} // namespace rosarch
