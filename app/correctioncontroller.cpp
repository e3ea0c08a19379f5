#include "app/correctioncontroller.h"
#include "app/correctionlookup.h"
#include "app/traceability.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "document/nodedescription.h"
#include "jobs/stallprobe.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/correctiondialog.h"
#include "widgets/correctionmodel.h"
#include "widgets/correctionpanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramview.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"

#include <QAction>
#include <QMenu>
#include <QRegularExpression>
#include <QSet>
#include <QTreeView>
#include <QUndoStack>

namespace rosarch {

namespace {

using Kind = CorrectionController::Element::Kind;
using namespace CorrectionLookup;

} // namespace

CorrectionController::CorrectionController(Document *document, AtomicNodePanel *nodePanel,
                                           LaunchTreePanel *launchPanel, DiagramPanel *diagramPanel,
                                           Traceability *traceability, InspectorPanel *inspector,
                                           CorrectionPanel *corrections, QWidget *window)
    : QObject(window), m_document(document), m_nodePanel(nodePanel), m_launchPanel(launchPanel),
      m_diagramPanel(diagramPanel), m_traceability(traceability), m_inspector(inspector),
      m_corrections(corrections), m_window(window)
{
    connect(document, &Document::changed, this, [this](const DocumentChange &change) {
        const StallScope scope("CorrectionController (document changed)");
        m_index.reset();
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
    connect(nodePanel, &AtomicNodePanel::contextMenuRequested, this,
            [this](QMenu *menu, const QModelIndex &index) {
                addMenuActions(menu, nodeElement(index));
            });
    connect(nodePanel, &AtomicNodePanel::renameRequested, this,
            [this](const QModelIndex &index) { rename(nodeElement(index)); });
    connect(launchPanel, &LaunchTreePanel::contextMenuRequested, this,
            [this](QMenu *menu, const QModelIndex &index) {
                addMenuActions(menu, launchElement(index));
            });
    connect(diagramPanel, &DiagramPanel::elementMenuRequested, this,
            [this](const QString &key, QMenu *menu) {
                const Element e = diagramElement(key);
                addMenuActions(menu, e);
                // several parts of one root: a subsystem
                QStringList ids;
                for (const QString &k : m_diagramPanel->selectedKeys() + QStringList{key}) {
                    const Element part = diagramElement(k);
                    if (part.kind == Kind::Instance && !ids.contains(part.id) &&
                        part.rootId == e.rootId)
                        ids.append(part.id);
                }
                if (e.kind == Kind::Instance && ids.size() >= 2) {
                    menu->addSeparator();
                    QAction *g = menu->addAction(tr("&Group Selected Parts into Subsystem\u2026"));
                    connect(g, &QAction::triggered, this,
                            [this, ids, root = e.rootId] { group(ids, root); });
                }
            });
    connect(corrections, &CorrectionPanel::correctionActivated, this,
            &CorrectionController::showCorrection);
    connect(corrections, &CorrectionPanel::removeRequested, this, [this](const QStringList &ids) {
        if (ids.size() == 1) {
            m_document->session()->removeCorrection(ids.first());
            return;
        }
        m_document->undoStack()->beginMacro(tr("Remove %1 corrections").arg(ids.size()));
        for (const QString &id : ids)
            m_document->session()->removeCorrection(id);
        m_document->undoStack()->endMacro();
    });
    connect(corrections, &CorrectionPanel::retargetRequested, this,
            &CorrectionController::retarget);
    installShortcuts();
    refreshInspector();
}

void CorrectionController::setDialogHandler(std::function<bool(CorrectionDialog &)> handler)
{
    m_dialogHandler = std::move(handler);
}

const CorrectionIndex &CorrectionController::index()
{
    if (!m_index)
        m_index = CorrectionIndex(*m_document);
    return *m_index;
}

QString CorrectionController::keyOf(const QString &id)
{
    if (StableKeys::isChannelKey(id))
        return id;
    if (index().isEmpty()) // no corrections: the model as recovered is the corrected one
        return m_document->session()->keyOf(id);
    return index().keyOf(id);
}

bool CorrectionController::keysAtHand(const QString &id)
{
    return StableKeys::isChannelKey(id) || !index().isEmpty() || m_document->session()->keysReady();
}

bool CorrectionController::ask(CorrectionDialog &dialog)
{
    if (m_dialogHandler)
        return m_dialogHandler(dialog) && dialog.isComplete();
    return dialog.exec() == QDialog::Accepted;
}

bool CorrectionController::push(Correction c)
{
    if (c.target.isEmpty())
        return false;
    const QString id = m_document->session()->addCorrection(c);
    if (id.isEmpty())
        return false;
    Q_EMIT statusMessage(tr("%1: %2 (Ctrl+Z undoes it)")
                             .arg(id, CorrectionModel::kindText(int(c.kind)) + u' ' + c.summary()),
                         6000);
    return true;
}

void CorrectionController::setCurrent(const Element &element)
{
    if (element == m_current)
        return;
    m_current = element;
    refreshInspector();
}

void CorrectionController::refreshInspector()
{
    if (!m_inspector)
        return;
    m_inspector->setElement(describe(m_current), actionsFor(m_current, m_inspector));
}

CorrectionController::Element CorrectionController::nodeElement(const QModelIndex &index) const
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

CorrectionController::Element CorrectionController::launchElement(const QModelIndex &index) const
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

CorrectionController::Element CorrectionController::diagramElement(const QString &key) const
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

bool CorrectionController::isRemoved(const Element &element)
{
    if (element.kind != Kind::Class && element.kind != Kind::Port && element.kind != Kind::Instance)
        return false;
    return !index().removedBy(element.id).isEmpty();
}

QString CorrectionController::nameOf(const Element &e)
{
    const Recovery &now = m_document->accepted();
    switch (e.kind) {
    case Kind::Class:
        if (const AtomicNode *n = now.nodes.node(e.id))
            return n->className;
        if (const AtomicNode *n = m_document->atomicNodes().node(e.id))
            return n->className;
        return {};
    case Kind::Port:
        if (const Port *p = findPort(now.nodes, e.id))
            return portName(*p);
        if (const Port *p = findPort(m_document->atomicNodes(), e.id))
            return portName(*p);
        return {};
    case Kind::Instance:
    case Kind::Connection:
        if (const NodeInstance *n = now.launch.node(e.id))
            return instanceName(*n);
        if (const NodeInstance *n = m_document->launchDependencies().node(e.id))
            return instanceName(*n);
        return {};
    case Kind::LaunchFile:
        if (const LaunchFileInstance *lf = now.launch.instance(e.id))
            return lf->file.isEmpty() ? lf->type : lf->file.section(u'/', -1);
        return {};
    case Kind::Channel:
        return e.id.section(u':', 1);
    case Kind::None:
        break;
    }
    return {};
}

void CorrectionController::describeClass(InspectorInfo &info, const QString &classId) const
{
    // one query for every view that shows a description (node list, inspector, diagram)
    const NodeDescription d = NodeDescription::of(*m_document, classId);
    info.describable = true;
    info.description = d.text;
    info.descriptionSource = d.sourceText();
}

InspectorInfo CorrectionController::describe(const Element &e)
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
    info.name = nameOf(e);
    if (!keysAtHand(e.id)) {
        info.key = tr("(being worked out\u2026)"); // shown when the keys are made
    } else {
        info.key = keyOf(e.kind == Kind::Connection ? e.port : e.id);
        if (e.kind == Kind::Connection)
            info.key = keyOf(e.id) + QStringLiteral(" \u00b7 ") + info.key;
    }
    QStringList by;
    const QList<Correction> touching = index().of(e.id);
    for (const Correction &c : touching)
        if (c.kind != Correction::Kind::Review)
            by.append(c.id);
    if (const QString removed = index().removedBy(e.id); !removed.isEmpty())
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
    info.corrections = index().summary(e.id);
    return info;
}

QList<QAction *> CorrectionController::actionsFor(const Element &e, QObject *parent)
{
    QList<QAction *> actions;
    const auto add = [&](const QString &text, const QKeySequence &shortcut, auto fn) {
        auto *a = new QAction(text, parent);
        if (!shortcut.isEmpty()) {
            a->setShortcut(shortcut);
            a->setShortcutContext(Qt::WidgetShortcut); // shown; the views own the keys
        }
        connect(a, &QAction::triggered, this, [e, fn] { fn(e); });
        actions.append(a);
        return a;
    };
    if (e.kind == Kind::None || describe(e).kind.isEmpty())
        return actions;
    if (isRemoved(e)) {
        add(tr("Restore (Revert %1)").arg(index().removedBy(e.id)), {},
            [this](const Element &x) { restore(x); });
        return actions;
    }
    const QKeySequence review(tr("Ctrl+R"));
    const QString reviewText = describe(e).reviewed ? tr("Unmark Reviewed") : tr("Mark Re&viewed");
    switch (e.kind) {
    case Kind::Class:
        add(tr("Add &Port\u2026"), {}, [this](const Element &x) { addPort(x); });
        add(tr("Re&move Class\u2026"), QKeySequence::Delete,
            [this](const Element &x) { remove(x); });
        break;
    case Kind::Port: {
        const Port *p = findPort(m_document->accepted().nodes, e.id);
        const bool expression = p && !p->isResolved();
        add(expression ? tr("Set &Name\u2026") : tr("Re&name\u2026"), Qt::Key_F2,
            [this](const Element &x) { rename(x); });
        QAction *type = add(tr("Set &Type\u2026"), {}, [this](const Element &x) { setType(x); });
        if (p && !isCanonicalInterfaceType(p->type))
            type->setText(tr("Set &Type\u2026 (unknown)"));
        add(tr("Re&move Port\u2026"), QKeySequence::Delete,
            [this](const Element &x) { remove(x); });
        break;
    }
    case Kind::Instance:
        add(tr("Re&name\u2026"), Qt::Key_F2, [this](const Element &x) { rename(x); });
        add(tr("Re&move\u2026"), QKeySequence::Delete, [this](const Element &x) { remove(x); });
        add(tr("Add &Connection\u2026"), {}, [this](const Element &x) { addConnection(x); });
        break;
    case Kind::LaunchFile:
        add(tr("Add &Part\u2026"), {}, [this](const Element &x) { addPart(x); });
        return actions; // a launch file is not reviewed on its own
    case Kind::Channel:
        add(tr("Re&name\u2026"), Qt::Key_F2, [this](const Element &x) { rename(x); });
        break;
    case Kind::Connection:
        if (!keysAtHand(e.port) || !keyOf(e.port).isEmpty())
            add(tr("Remove &Connection\u2026"), QKeySequence::Delete,
                [this](const Element &x) { remove(x); });
        return actions;
    case Kind::None:
        break;
    }
    add(reviewText, review, [this](const Element &x) { toggleReviewed(x); });
    return actions;
}

void CorrectionController::addMenuActions(QMenu *menu, const Element &element)
{
    const QList<QAction *> actions = actionsFor(element, menu);
    if (actions.isEmpty())
        return;
    menu->addSection(tr("Correct"));
    menu->addActions(actions);
}

void CorrectionController::showCorrection(const QString &id)
{
    const Correction *c = m_document->session()->correction(id);
    if (!c)
        return;
    const QString family = StableKeys::family(c->target);
    QString elementId = index().idOf(c->target);
    if (c->kind == Correction::Kind::AddPart) // the part it added, in its first launch file
        for (const NodeInstance &n : m_document->accepted().launch.nodes)
            if (n.id.startsWith(c->id + u'_')) {
                elementId = n.id;
                break;
            }
    if (family == QLatin1String("launch"))
        for (const LaunchFileInstance &lf : m_document->accepted().launch.instances)
            if (StableKeys::launchKey(lf) == c->target && elementId.isEmpty())
                elementId = lf.id;
    if (StableKeys::isChannelKey(c->target)) {
        QString name = c->target.section(u':', 1);
        if (c->kind == Correction::Kind::Rename)
            name = c->newValue;
        const Element e{Kind::Channel, family + u':' + name, {}, {}};
        if (const Composite *shown =
                m_diagramPanel->architecture().composite(m_diagramPanel->currentComposite()))
            for (const Channel &ch : shown->channels)
                if (channelFamily(ch.kind) == family && ch.name == name)
                    m_diagramPanel->selectElement(DiagramBuilder::channelKey(ch.id));
        setCurrent(e);
        return;
    }
    if (elementId.isEmpty())
        return; // orphaned: nothing to show
    if (family == QLatin1String("class")) {
        m_traceability->selectNode(elementId);
    } else if (family == QLatin1String("port")) {
        m_traceability->selectNode(elementId.section(u'/', 0, 0), elementId.section(u'/', 1));
    } else {
        m_traceability->selectLaunchItem(elementId);
        m_diagramPanel->selectInstance(elementId);
    }
}

void CorrectionController::installShortcuts()
{
    // The keys act on the view that has the focus: F2 renames, Delete removes, Ctrl+R marks
    // reviewed. The node list keeps F2 for a class's description (AtomicNodePanel).
    const auto install = [this](QWidget *view, std::function<Element()> current, bool f2) {
        const auto make = [&](const QKeySequence &keys, auto fn) {
            auto *a = new QAction(view);
            a->setShortcut(keys);
            a->setShortcutContext(Qt::WidgetShortcut);
            connect(a, &QAction::triggered, this, [current, fn] { fn(current()); });
            view->addAction(a);
        };
        if (f2)
            make(Qt::Key_F2, [this](const Element &e) { rename(e); });
        make(QKeySequence::Delete, [this](const Element &e) { remove(e); });
        make(QKeySequence(tr("Ctrl+R")), [this](const Element &e) { toggleReviewed(e); });
    };
    install(
        m_nodePanel->treeView(), [this] { return nodeElement(m_nodePanel->currentSourceIndex()); },
        false);
    install(
        m_launchPanel->treeView(),
        [this] { return launchElement(m_launchPanel->currentSourceIndex()); }, true);
    install(
        m_diagramPanel->view(),
        [this] {
            const QStringList keys = m_diagramPanel->selectedKeys();
            return keys.isEmpty() ? Element{} : diagramElement(keys.first());
        },
        true);
}

} // namespace rosarch
