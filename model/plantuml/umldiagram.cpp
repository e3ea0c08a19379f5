#include "plantuml/umldiagram.h"

#include <QHash>

namespace rosarch {

QString umlLevelName(UmlLevel level)
{
    switch (level) {
    case UmlLevel::Acd:
        return QStringLiteral("acd");
    case UmlLevel::Ccd:
        return QStringLiteral("ccd");
    case UmlLevel::Unknown:
        break;
    }
    return QStringLiteral("unknown");
}

QStringList umlKinds(UmlLevel level)
{
    using namespace UmlKind;
    if (level == UmlLevel::Acd)
        return {ArcName,     ArcStereotype,   MessageType, Callback,
                ServiceType, ServiceFunction, ActionType,  ActionFunction};
    if (level == UmlLevel::Ccd)
        return {Part, PartType, Namespace, Topic, Service, Action, BoundaryPort, Connection};
    return {};
}

QString umlKindLabel(const QString &kind)
{
    static const QHash<QString, QString> labels = {
        {UmlKind::ArcName, QStringLiteral("ARC name")},
        {UmlKind::ArcStereotype, QStringLiteral("ARC stereotype")},
        {UmlKind::MessageType, QStringLiteral("message type")},
        {UmlKind::Callback, QStringLiteral("callback function")},
        {UmlKind::ServiceType, QStringLiteral("service type")},
        {UmlKind::ServiceFunction, QStringLiteral("service function")},
        {UmlKind::ActionType, QStringLiteral("action type")},
        {UmlKind::ActionFunction, QStringLiteral("action function")},
        {UmlKind::Part, QStringLiteral("RosNodePart")},
        {UmlKind::PartType, QStringLiteral("part type")},
        {UmlKind::Namespace, QStringLiteral("namespace membership")},
        {UmlKind::Topic, QStringLiteral("topic")},
        {UmlKind::Service, QStringLiteral("service")},
        {UmlKind::Action, QStringLiteral("action")},
        {UmlKind::BoundaryPort, QStringLiteral("boundary port")},
        {UmlKind::Connection, QStringLiteral("connection")},
    };
    return labels.value(kind, kind);
}

QStringList UmlDiagram::values(const QString &kind) const
{
    QStringList out;
    for (const UmlElement &e : elements)
        if (e.kind == kind)
            out << e.value;
    return out;
}

} // namespace rosarch
