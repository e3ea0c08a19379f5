#include "widgets/diagram/diagramtext.h"
#include "core/visibletext.h"
#include "diagram/diagrambuilder.h"

namespace rosarch {

namespace {

QString where(const Evidence &e)
{
    return e.isValid() ? QStringLiteral("%1:%2").arg(e.file).arg(e.line) : QString();
}

QString portKindText(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return DiagramText::tr("Publisher");
    case PortKind::Subscriber:
        return DiagramText::tr("Subscriber");
    case PortKind::ServiceServer:
        return DiagramText::tr("Service server");
    case PortKind::ServiceClient:
        return DiagramText::tr("Service client");
    case PortKind::ActionServer:
        return DiagramText::tr("Action server");
    case PortKind::ActionClient:
        return DiagramText::tr("Action client");
    }
    return {};
}

QString connectionText(Connection::Kind kind)
{
    switch (kind) {
    case Connection::Kind::Publish:
        return DiagramText::tr("publishes to");
    case Connection::Kind::Subscribe:
        return DiagramText::tr("subscribes to");
    case Connection::Kind::Client:
        return DiagramText::tr("calls");
    case Connection::Kind::Server:
        return DiagramText::tr("serves");
    case Connection::Kind::DelegationIn:
    case Connection::Kind::DelegationOut:
        return DiagramText::tr("is delegated to the boundary port");
    }
    return {};
}

QString lines(QStringList l)
{
    l.removeAll(QString());
    return l.join(QLatin1Char('\n'));
}

QString partToolTip(const RosNodePart &part)
{
    QStringList l;
    if (part.kind == RosNodePart::Kind::Launch) {
        l << (part.external ? DiagramText::tr("Included launch file %1 (outside the workspace)")
                            : DiagramText::tr("Included launch file %1 — double-click to open"))
                 .arg(part.typeName);
        if (part.external && !part.ports.isEmpty() && !part.ports.first().model.isEmpty())
            l << DiagramText::tr("The ports of its nodes come from the interface model %1.")
                     .arg(part.ports.first().model);
    } else {
        l << DiagramText::tr("Node %1 : %2").arg(part.name, part.typeName);
        if (!part.typed && part.ports.isEmpty())
            l << DiagramText::tr("The class was not found; its ports are unknown.");
        else if (!part.typed)
            l << DiagramText::tr("Outside the workspace; its ports come from an interface model.");
    }
    l << DiagramText::tr("Namespace: %1")
             .arg(part.nameSpace.isEmpty() ? QStringLiteral("/") : part.nameSpace);
    if (!part.active)
        l << DiagramText::tr("Inactive: its launch condition is false.");
    l << DiagramText::tr("Started at %1").arg(where(part.evidence));
    return lines(l);
}

QString portToolTip(const PartPort &port)
{
    QStringList l;
    l << QStringLiteral("%1 %2").arg(portKindText(port.kind), port.name);
    l << port.type;
    if (!port.nameAsWritten.isEmpty() && port.nameAsWritten != port.name)
        l << DiagramText::tr("Written as: %1").arg(port.nameAsWritten);
    if (!port.resolved)
        l << DiagramText::tr("The name could not be resolved statically; this is a guess.");
    else if (port.guessed)
        l << (port.remapped
                  ? DiagramText::tr("Remapped to a name built from a launch value nobody sets; "
                                    "the name is a guess.")
                  : DiagramText::tr("Its namespace or node name is built from a launch value "
                                    "nobody sets; the name is a guess, wired only to names that "
                                    "rest on a guess too."));
    if (port.parameterDerived)
        l << DiagramText::tr("The name comes from a parameter.");
    if (port.remapped)
        l << DiagramText::tr("Remapped by the launch file.");
    if (!port.guard.isEmpty())
        l << (port.active ? DiagramText::tr("Guard: %1")
                          : DiagramText::tr("Guard (false here): %1"))
                 .arg(port.guard);
    if (!port.model.isEmpty()) // code outside the workspace: the place is the launch action
        l << DiagramText::tr("From the interface model %1 (code outside the workspace), "
                             "started at %2")
                 .arg(port.model, where(port.evidence));
    else
        l << DiagramText::tr("Created at %1").arg(where(port.evidence));
    return lines(l);
}

} // namespace

QHash<QString, QString> DiagramText::toolTips(const Composite &c)
{
    QHash<QString, QString> out;
    for (const RosNodePart &part : c.parts) {
        out.insert(DiagramBuilder::partKey(part.id), partToolTip(part));
        for (const PartPort &port : part.ports)
            out.insert(DiagramBuilder::portKey(part.id, port.id), portToolTip(port));
        for (const QString &ns : DiagramBuilder::namespaceChain(part.nameSpace))
            out.insert(DiagramBuilder::namespaceKey(ns),
                       tr("Namespace %1 — right-click to collapse or expand").arg(ns));
    }
    for (const Channel &ch : c.channels) {
        QString kind = ch.kind == Channel::Kind::Topic     ? tr("Topic %1")
                       : ch.kind == Channel::Kind::Service ? tr("Service %1")
                                                           : tr("Action %1");
        out.insert(DiagramBuilder::channelKey(ch.id), lines({kind.arg(ch.name), ch.type}));
    }
    for (const BoundaryPort &b : c.boundary) {
        QStringList l{tr("Boundary port %1: %2 %3").arg(b.id, portKindText(b.kind), b.name), b.type,
                      tr("Promoted: nothing inside this launch file is on the other side.")};
        if (b.guessed)
            l << tr("The name rests on a launch value nobody sets; it is a guess.");
        out.insert(DiagramBuilder::boundaryKey(b.id), lines(l));
    }
    for (int i = 0; i < c.connections.size(); ++i) {
        const Connection &conn = c.connections[i];
        const RosNodePart *part = c.part(conn.partId);
        const QString who =
            part ? (part->name.isEmpty() ? part->typeName : part->name) : conn.partId;
        const Channel *ch = c.channel(conn.targetId);
        const QString what = ch ? ch->name : conn.targetId;
        out.insert(DiagramBuilder::connectionKey(i),
                   tr("%1 (%2) %3 %4 — click to see the code")
                       .arg(who, conn.portId, connectionText(conn.kind), what));
    }
    return out;
}

QString DiagramText::missingBanner(const QStringList &missing)
{
    if (missing.isEmpty())
        return {};
    const int shown = 6;
    QString list = QStringList(missing.mid(0, shown)).join(QStringLiteral(", "));
    if (missing.size() > shown)
        list += QStringLiteral(", …");
    return missing.size() == 1
               ? tr("1 element of the reference is missing: %1").arg(list)
               : tr("%1 elements of the reference are missing: %2").arg(missing.size()).arg(list);
}

QString DiagramText::frameDetail(const Composite &c)
{
    if (!c.executable.isEmpty()) // a main that builds its nodes itself
        return tr("executable, nodes built in %1").arg(visibleText(c.file));
    return c.file.isEmpty() ? tr("launch file (outside the workspace)")
                            : tr("launch file %1").arg(visibleText(c.file));
}

} // namespace rosarch
