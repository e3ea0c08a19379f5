#include "app/changeselector.h"
#include "app/traceability.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "widgets/architecturediffview.h"
#include "widgets/diagram/diagrampanel.h"

namespace rosarch {

namespace {

/// The key ArchitectureSnapshot gives a part: "/ns/name" for a node, ":type" (and " in /ns")
/// for an included launch file.
QString snapshotKey(const RosNodePart &part)
{
    const QString ns = part.nameSpace == QLatin1String("/") ? QString() : part.nameSpace;
    if (part.kind == RosNodePart::Kind::Node)
        return ns + u'/' + part.name;
    return u':' + part.typeName + (ns.isEmpty() ? QString() : QStringLiteral(" in ") + ns);
}

/// "/x (std_msgs/msg/T)" → "/x"; a name written without its type stays as it is.
QString withoutType(const QString &text)
{
    const qsizetype open = text.lastIndexOf(QStringLiteral(" ("));
    return open >= 0 && text.endsWith(u')') ? text.left(open) : text;
}

} // namespace

ChangeSelector::ChangeSelector(Document *document, ArchitectureDiffView *view,
                               Traceability *traceability, DiagramPanel *diagram, QObject *parent)
    : QObject(parent), m_document(document), m_traceability(traceability), m_diagram(diagram)
{
    connect(view, &ArchitectureDiffView::changeSelected, this,
            [this](const ArchitectureChange &change) { select(change); });
}

bool ChangeSelector::select(const ArchitectureChange &change)
{
    disconnect(m_pending);
    const bool removed = change.kind == ArchitectureChange::Kind::Removed;
    const QString text = removed ? change.before : change.after;
    bool found = false;
    if (change.element == QLatin1String("node class"))
        found = selectClass(text);
    else if (change.element == QLatin1String("port"))
        found = selectPort(change.scope, text);
    else if (change.element == QLatin1String("launch file"))
        found = selectLaunchFile(change.scope);
    else
        found = selectInComposite(change, text);
    if (!found) {
        // The nearest thing that is there: the class of a port, the launch file of a part.
        if (change.element == QLatin1String("port"))
            for (const AtomicNode &n : m_document->accepted().nodes.nodes)
                if (n.className == change.scope) {
                    m_traceability->selectNode(n.id);
                    break;
                }
        Q_EMIT statusMessage(
            removed ? tr("The %1 %2 was removed: it is not in the model shown.")
                          .arg(change.element, text)
                    : tr("The %1 %2 is not in the model shown.").arg(change.element, text),
            6000);
    }
    return found;
}

bool ChangeSelector::selectClass(const QString &key)
{
    for (const AtomicNode &n : m_document->accepted().nodes.nodes) {
        const QString nodeKey =
            n.packageName + u'/' + (n.qualifiedName.isEmpty() ? n.className : n.qualifiedName);
        if (nodeKey == key) {
            m_traceability->goToClass(n.id);
            return true;
        }
    }
    return false;
}

bool ChangeSelector::selectPort(const QString &className, const QString &portText)
{
    // "publisher /scan (sensor_msgs/msg/LaserScan)", as ArchitectureDiff writes a port
    const QString kind = portText.section(u' ', 0, 0);
    const QString name = withoutType(portText.mid(kind.size() + 1));
    for (const AtomicNode &n : m_document->accepted().nodes.nodes) {
        if (n.className != className)
            continue;
        for (const Port &p : n.ports)
            if (portKindName(p.kind) == kind && p.name == name) {
                m_traceability->selectNode(n.id, p.id);
                return true;
            }
    }
    return false;
}

bool ChangeSelector::selectLaunchFile(const QString &file)
{
    for (const LaunchFileInstance &lf : m_document->accepted().launch.instances)
        if (lf.file == file) {
            m_traceability->selectLaunchItem(lf.id);
            return true;
        }
    return false;
}

bool ChangeSelector::selectInComposite(const ArchitectureChange &change, const QString &text)
{
    // The composite of the change's launch file: the one shown if it is that file's.
    const Architecture &architecture = m_diagram->architecture();
    const Composite *composite = architecture.composite(m_diagram->currentComposite());
    if (!composite || composite->file != change.scope) {
        composite = nullptr;
        for (const Composite &c : architecture.composites)
            if (c.file == change.scope) {
                composite = &c;
                break;
            }
    }
    if (!composite)
        return false;
    if (change.element == QLatin1String("part") || change.element == QLatin1String("connection")) {
        // "/ns/name : Type" for a part; "/ns/name publishes topic /x" for a connection
        for (const RosNodePart &part : composite->parts) {
            const QString key = snapshotKey(part);
            if (text == key + QStringLiteral(" : ") + part.typeName ||
                text.startsWith(key + u' ')) {
                m_traceability->selectLaunchItem(part.instanceId); // the diagram follows
                return true;
            }
        }
        return false;
    }
    const QString name = withoutType(text);
    for (const Channel &ch : composite->channels)
        if (channelKindName(ch.kind) == change.element && ch.name == name) {
            if (m_diagram->currentComposite() != composite->instanceId)
                m_diagram->showComposite(composite->instanceId);
            selectWhenLaidOut(DiagramBuilder::channelKey(ch.id));
            return true;
        }
    return false;
}

void ChangeSelector::selectWhenLaidOut(const QString &diagramKey)
{
    if (!m_diagram->isLayingOut()) {
        m_diagram->selectElement(diagramKey);
        return;
    }
    m_pending =
        connect(m_diagram, &DiagramPanel::layoutFinished, this, [this, diagramKey](bool ok) {
            disconnect(m_pending);
            if (ok)
                m_diagram->selectElement(diagramKey);
        });
}

} // namespace rosarch
