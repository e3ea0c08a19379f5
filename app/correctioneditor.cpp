#include "app/correctioneditor.h"
#include "app/correctionlookup.h"
#include "app/correctiontargets.h"
#include "document/document.h"
#include "widgets/correctiondialog.h"
#include "widgets/correctionmodel.h"

#include <QSet>
#include <QUndoStack>

#include <algorithm>

namespace rosarch {

namespace {

using Kind = CorrectionElement::Kind;
using namespace CorrectionLookup;

} // namespace

CorrectionEditor::CorrectionEditor(Document *document, CorrectionTargets *targets, QWidget *window,
                                   QObject *parent)
    : QObject(parent), m_document(document), m_targets(targets), m_window(window)
{
}

void CorrectionEditor::setDialogHandler(std::function<bool(CorrectionDialog &)> handler)
{
    m_dialogHandler = std::move(handler);
}

bool CorrectionEditor::ask(CorrectionDialog &dialog)
{
    if (m_dialogHandler)
        return m_dialogHandler(dialog) && dialog.isComplete();
    return dialog.exec() == QDialog::Accepted;
}

bool CorrectionEditor::push(Correction c)
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

QStringList CorrectionEditor::knownTypes()
{
    QSet<QString> types;
    for (const AtomicNode &n : m_document->accepted().nodes.nodes)
        for (const Port &p : n.ports)
            if (isCanonicalInterfaceType(p.type))
                types.insert(p.type);
    QStringList out(types.cbegin(), types.cend());
    out.sort();
    return out;
}

bool CorrectionEditor::rename(const CorrectionElement &e)
{
    if (m_targets->isRemoved(e))
        return false;
    Correction c;
    c.kind = Correction::Kind::Rename;
    const QString old = m_targets->nameOf(e);
    QString title = tr("Rename");
    QString what;
    QStringList twins; ///< the other unresolved ports of the class written the same way
    switch (e.kind) {
    case Kind::Port: {
        const Port *p = findPort(m_document->accepted().nodes, e.id);
        if (!p)
            return false;
        c.target = m_targets->keyOf(e.id);
        if (!p->isResolved()) {
            c.kind = Correction::Kind::SetName;
            title = tr("Set Name");
            what = tr("Analysis left the name of this %1 as an expression: %2. Give the name it "
                      "has at run time.")
                       .arg(portKindName(p->kind), old);
            twins = twinPorts(e.id);
        } else {
            what = tr("Rename the %1 %2 of this class (every instance uses the new name).")
                       .arg(portKindName(p->kind), old);
        }
        break;
    }
    case Kind::Instance:
        c.target = m_targets->keyOf(e.id);
        what = tr("Rename the node instance %1.").arg(old);
        break;
    case Kind::Channel: {
        c.target = e.id;
        // a renamed one is renamed again from where it came from
        for (const Correction &earlier : m_document->session()->corrections())
            if (earlier.kind == Correction::Kind::Rename &&
                StableKeys::family(earlier.target) == StableKeys::family(e.id) &&
                StableKeys::family(e.id) + u':' + earlier.newValue == e.id)
                c.target = earlier.target;
        what = tr("Rename %1 everywhere it is used.").arg(e.id);
        break;
    }
    default:
        return false;
    }
    CorrectionDialog dialog(title, what, CorrectionDialog::Name, m_window);
    dialog.setName(old);
    if (!twins.isEmpty())
        dialog.setAlso(twins.size() == 1
                           ? tr("Also name the 1 other port of this class written %1 so").arg(old)
                           : tr("Also name the %1 other ports of this class written %2 so")
                                 .arg(twins.size())
                                 .arg(old));
    if (!ask(dialog) || dialog.name() == old)
        return false;
    c.oldValue = old;
    c.newValue = dialog.name();
    c.reason = dialog.reason();
    if (!dialog.also())
        return push(c);
    // One step to undo: the port and its twins.
    QUndoStack *stack = m_document->undoStack();
    stack->beginMacro(tr("Set Name of %1 ports").arg(twins.size() + 1));
    int named = push(c) ? 1 : 0;
    for (const QString &twin : std::as_const(twins)) {
        c.target = m_targets->keyOf(twin);
        named += push(c) ? 1 : 0;
    }
    stack->endMacro();
    Q_EMIT statusMessage(tr("Named %1 ports written %2 as “%3” (Ctrl+Z undoes them)")
                             .arg(named)
                             .arg(old, c.newValue),
                         8000);
    return named > 0;
}

QStringList CorrectionEditor::twinPorts(const QString &portId)
{
    const QString nodeId = portId.section(u'/', 0, 0);
    const AtomicNode *node = m_document->accepted().nodes.node(nodeId);
    const Port *port = findPort(m_document->accepted().nodes, portId);
    QStringList twins;
    if (!node || !port)
        return twins;
    for (const Port &other : node->ports) {
        const QString id = nodeId + u'/' + other.id;
        CorrectionElement twin;
        twin.kind = Kind::Port;
        twin.id = id;
        if (id != portId && !other.isResolved() && portName(other) == portName(*port) &&
            !m_targets->isRemoved(twin))
            twins.append(id);
    }
    return twins;
}

bool CorrectionEditor::setType(const CorrectionElement &e)
{
    const Port *p = e.kind == Kind::Port ? findPort(m_document->accepted().nodes, e.id) : nullptr;
    if (!p || m_targets->isRemoved(e))
        return false;
    CorrectionDialog dialog(
        tr("Set Type"),
        isCanonicalInterfaceType(p->type)
            ? tr("Override the interface type of the %1 %2.")
                  .arg(portKindName(p->kind), portName(*p))
            : tr("Analysis could not decide the interface type of the %1 %2 (%3).")
                  .arg(portKindName(p->kind), portName(*p),
                       p->type.isEmpty() ? tr("unknown") : p->type),
        CorrectionDialog::Type, m_window);
    dialog.setTypeChoices(knownTypes());
    dialog.setType(isCanonicalInterfaceType(p->type) ? p->type : QString());
    dialog.setTypeRequired(true);
    if (!ask(dialog) || dialog.type() == p->type)
        return false;
    Correction c;
    c.kind = Correction::Kind::SetType;
    c.target = m_targets->keyOf(e.id);
    c.oldValue = p->type;
    c.newValue = dialog.type();
    c.reason = dialog.reason();
    return push(c);
}

bool CorrectionEditor::remove(const CorrectionElement &e)
{
    if (m_targets->isRemoved(e))
        return false;
    Correction c;
    c.kind = Correction::Kind::Remove;
    QString what;
    switch (e.kind) {
    case Kind::Class:
        what = tr("Remove the class %1 from the model (analysis got it wrong).")
                   .arg(m_targets->nameOf(e));
        break;
    case Kind::Port:
        what = tr("Remove the port %1 from its class.").arg(m_targets->nameOf(e));
        break;
    case Kind::Instance:
        what = tr("Remove the node instance %1 (it is not started).").arg(m_targets->nameOf(e));
        break;
    case Kind::Connection: {
        c.port = m_targets->keyOf(e.port);
        if (c.port.isEmpty())
            return false;
        const Port *p = findPort(m_document->accepted().nodes, e.port);
        what = tr("Remove the connection of %1 through its %2 %3.")
                   .arg(m_targets->nameOf(e), p ? portKindName(p->kind) : QString(),
                        p ? portName(*p) : e.port);
        break;
    }
    default:
        return false;
    }
    c.target = m_targets->keyOf(e.id);
    CorrectionDialog dialog(tr("Remove"), what, CorrectionDialog::NoField, m_window);
    if (!ask(dialog))
        return false;
    c.oldValue = m_targets->nameOf(e);
    c.reason = dialog.reason();
    return push(c);
}

bool CorrectionEditor::addPort(const CorrectionElement &e)
{
    if (e.kind != Kind::Class || m_targets->isRemoved(e))
        return false;
    CorrectionDialog dialog(
        tr("Add Port"), tr("Add a port analysis missed to the class %1.").arg(m_targets->nameOf(e)),
        CorrectionDialog::Kind | CorrectionDialog::Name | CorrectionDialog::Type, m_window);
    dialog.setNameLabel(tr("&Name:"));
    dialog.setTypeChoices(knownTypes());
    if (!ask(dialog))
        return false;
    Correction c;
    c.kind = Correction::Kind::AddPort;
    c.target = m_targets->keyOf(e.id);
    c.portKind = dialog.portKind();
    c.newValue = dialog.name();
    c.type = dialog.type();
    c.reason = dialog.reason();
    return push(c);
}

bool CorrectionEditor::addPart(const CorrectionElement &e)
{
    const LaunchFileInstance *lf =
        e.kind == Kind::LaunchFile ? m_document->accepted().launch.instance(e.id) : nullptr;
    if (!lf || lf->file.isEmpty())
        return false;
    QList<QPair<QString, QString>> classes;
    for (const AtomicNode &n : m_document->accepted().nodes.nodes)
        if (!n.isPlugin())
            classes.append({QStringLiteral("%1 (%2)").arg(n.className, n.packageName),
                            StableKeys::classKey(n)});
    std::sort(classes.begin(), classes.end());
    CorrectionDialog dialog(
        tr("Add Part"),
        tr("Add a node instance that %1 does not declare (started elsewhere).").arg(lf->file),
        CorrectionDialog::Choice | CorrectionDialog::Name | CorrectionDialog::Namespace, m_window);
    dialog.setChoices(tr("&Class:"), classes);
    dialog.setNameLabel(tr("Node &name:"));
    if (!ask(dialog))
        return false;
    Correction c;
    c.kind = Correction::Kind::AddPart;
    c.target = StableKeys::launchKey(*lf);
    c.classKey = dialog.choice();
    c.newValue = dialog.name();
    c.nameSpace = dialog.nameSpace();
    c.reason = dialog.reason();
    return push(c);
}

bool CorrectionEditor::addConnection(const CorrectionElement &e)
{
    if (e.kind != Kind::Instance || m_targets->isRemoved(e))
        return false;
    CorrectionDialog dialog(
        tr("Add Connection"),
        tr("Connect the node instance %1 to a topic, service or action analysis missed.")
            .arg(m_targets->nameOf(e)),
        CorrectionDialog::Kind | CorrectionDialog::Name | CorrectionDialog::Type, m_window);
    dialog.setNameLabel(tr("&On (absolute name):"));
    dialog.setName(QStringLiteral("/"));
    dialog.setTypeChoices(knownTypes());
    if (!ask(dialog))
        return false;
    Correction c;
    c.kind = Correction::Kind::AddConnection;
    c.target = m_targets->keyOf(e.id);
    c.portKind = dialog.portKind();
    c.newValue = dialog.name().startsWith(u'/') ? dialog.name() : u'/' + dialog.name();
    c.type = dialog.type();
    c.reason = dialog.reason();
    return push(c);
}

bool CorrectionEditor::toggleReviewed(const CorrectionElement &e)
{
    if (e.kind == Kind::None || e.kind == Kind::LaunchFile || e.kind == Kind::Connection ||
        m_targets->isRemoved(e))
        return false;
    const QString key = m_targets->keyOf(e.id);
    if (key.isEmpty())
        return false;
    QStringList marks;
    for (const Correction &c : m_document->session()->corrections())
        if (c.kind == Correction::Kind::Review && c.target == key)
            marks.append(c.id);
    if (!marks.isEmpty()) { // reviewed: the mark goes
        m_document->undoStack()->beginMacro(tr("Unmark %1 reviewed").arg(m_targets->nameOf(e)));
        for (const QString &id : std::as_const(marks))
            m_document->session()->removeCorrection(id);
        m_document->undoStack()->endMacro();
        return true;
    }
    Correction c;
    c.kind = Correction::Kind::Review;
    c.target = key;
    return push(c);
}

bool CorrectionEditor::group(const QStringList &instanceIds, const QString &rootId)
{
    const QString root = m_targets->keyOf(rootId);
    if (instanceIds.size() < 2 || StableKeys::family(root) != QLatin1String("include"))
        return false;
    QStringList members;
    QStringList names;
    for (const QString &id : instanceIds) {
        const QString key = m_targets->keyOf(id);
        if (key.isEmpty())
            return false;
        members.append(key);
        names.append(m_targets->nameOf({Kind::Instance, id, {}, {}}));
    }
    CorrectionDialog dialog(tr("Group into Subsystem"),
                            tr("Draw %1 as one subsystem.").arg(names.join(QStringLiteral(", "))),
                            CorrectionDialog::Name, m_window);
    dialog.setNameLabel(tr("Subsystem &name:"));
    if (!ask(dialog))
        return false;
    Correction c;
    c.kind = Correction::Kind::Group;
    c.target = root;
    c.members = members;
    c.newValue = dialog.name();
    c.reason = dialog.reason();
    return push(c);
}

bool CorrectionEditor::restore(const CorrectionElement &e)
{
    const QString id = m_targets->index().removedBy(e.id);
    return !id.isEmpty() && m_document->session()->removeCorrection(id);
}

bool CorrectionEditor::retarget(const QString &correctionId)
{
    const Correction *old = m_document->session()->correction(correctionId);
    if (!old)
        return false;
    const QString family = StableKeys::family(old->target);
    const Recovery &now = m_document->accepted();
    const StableKeys keys(now);
    QList<QPair<QString, QString>> choices;
    QSet<QString> seen;
    const auto offer = [&](const QString &text, const QString &key) {
        if (!key.isEmpty() && !seen.contains(key)) {
            seen.insert(key);
            choices.append({text, key});
        }
    };
    if (family == QLatin1String("class") || family == QLatin1String("port")) {
        for (const AtomicNode &n : now.nodes.nodes) {
            if (family == QLatin1String("class"))
                offer(QStringLiteral("%1 (%2)").arg(n.className, n.packageName), keys.keyOf(n.id));
            else
                for (const Port &p : n.ports)
                    offer(QStringLiteral("%1: %2 %3")
                              .arg(n.className, portKindName(p.kind), portName(p)),
                          keys.keyOf(n.id + u'/' + p.id));
        }
    } else if (family == QLatin1String("instance") || family == QLatin1String("part")) {
        for (const NodeInstance &n : now.launch.nodes)
            offer(QStringLiteral("%1 (%2)").arg(instanceName(n), n.nameSpace), keys.keyOf(n.id));
    } else if (family == QLatin1String("include") || family == QLatin1String("launch")) {
        for (const LaunchFileInstance &lf : now.launch.instances)
            if (!lf.file.isEmpty() && (family == QLatin1String("launch") || lf.parentId.isEmpty()))
                offer(lf.file, family == QLatin1String("launch") ? StableKeys::launchKey(lf)
                                                                 : keys.keyOf(lf.id));
    } else {
        for (const Composite &c : now.architecture.composites)
            for (const Channel &ch : c.channels)
                if (channelFamily(ch.kind) == family)
                    offer(ch.name, family + u':' + ch.name);
    }
    std::sort(choices.begin(), choices.end());
    if (choices.isEmpty()) {
        Q_EMIT statusMessage(tr("Nothing in this model can take %1").arg(old->id), 6000);
        return false;
    }
    CorrectionDialog dialog(
        tr("Re-target Correction"),
        tr("%1 (%2) names %3, which matches nothing now. Point it at:")
            .arg(old->id, CorrectionModel::kindText(int(old->kind)), old->target),
        CorrectionDialog::Choice, m_window);
    dialog.setChoices(tr("&Element:"), choices);
    dialog.setReason(old->reason);
    if (!ask(dialog))
        return false;
    Correction c = *old;
    c.target = dialog.choice();
    c.reason = dialog.reason();
    m_document->undoStack()->beginMacro(tr("Re-target %1").arg(c.id));
    m_document->session()->removeCorrection(c.id);
    const bool ok = !m_document->session()->addCorrection(c).isEmpty();
    m_document->undoStack()->endMacro();
    return ok;
}

void CorrectionEditor::removeCorrections(const QStringList &ids)
{
    if (ids.size() == 1) {
        m_document->session()->removeCorrection(ids.first());
        return;
    }
    m_document->undoStack()->beginMacro(tr("Remove %1 corrections").arg(ids.size()));
    for (const QString &id : ids)
        m_document->session()->removeCorrection(id);
    m_document->undoStack()->endMacro();
}

} // namespace rosarch
