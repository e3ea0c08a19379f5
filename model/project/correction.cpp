#include "project/correction.h"

#include <QJsonArray>

#include <array>
#include <utility>

namespace rosarch {

namespace {

constexpr std::array<std::pair<Correction::Kind, const char *>, 10> kKinds = {{
    {Correction::Kind::Rename, "rename"},
    {Correction::Kind::SetName, "set-name"},
    {Correction::Kind::SetType, "set-type"},
    {Correction::Kind::Remove, "remove"},
    {Correction::Kind::AddPort, "add-port"},
    {Correction::Kind::AddPart, "add-part"},
    {Correction::Kind::AddConnection, "add-connection"},
    {Correction::Kind::Group, "group"},
    {Correction::Kind::Review, "review"},
    {Correction::Kind::Describe, "describe"},
}};

bool hasPortKind(Correction::Kind kind)
{
    return kind == Correction::Kind::AddPort || kind == Correction::Kind::AddConnection;
}

} // namespace

QString Correction::kindName(Kind kind)
{
    for (const auto &[k, name] : kKinds)
        if (k == kind)
            return QLatin1String(name);
    return {};
}

bool Correction::kindFromName(const QString &name, Kind *kind)
{
    for (const auto &[k, n] : kKinds)
        if (name == QLatin1String(n)) {
            *kind = k;
            return true;
        }
    return false;
}

QString Correction::summary() const
{
    const QString arrow = QStringLiteral(" \u2192 ");
    switch (kind) {
    case Kind::Rename:
    case Kind::SetName:
    case Kind::SetType:
    case Kind::Describe:
        return oldValue + arrow + newValue;
    case Kind::Remove:
        return port.isEmpty() ? target : target + QLatin1Char(' ') + port;
    case Kind::AddPort:
    case Kind::AddConnection:
        return QStringLiteral("%1 %2 [%3]").arg(portKindName(portKind), newValue, type);
    case Kind::AddPart:
        return QStringLiteral("%1 (%2)").arg(newValue, classKey);
    case Kind::Group:
        return QStringLiteral("%1: %2").arg(newValue, members.join(QLatin1String(", ")));
    case Kind::Review:
        return target;
    }
    return {};
}

QJsonObject Correction::toJson() const
{
    QJsonObject o{{QLatin1String("id"), id},
                  {QLatin1String("kind"), kindName(kind)},
                  {QLatin1String("target"), target},
                  {QLatin1String("author"), author},
                  {QLatin1String("time"), time.toString(Qt::ISODate)}};
    auto put = [&o](const char *name, const QString &value) {
        if (!value.isEmpty())
            o.insert(QLatin1String(name), value);
    };
    put("old", oldValue);
    put("new", newValue);
    put("port", port);
    put("type", type);
    put("class", classKey);
    put("namespace", nameSpace);
    put("reason", reason);
    if (hasPortKind(kind))
        o.insert(QLatin1String("port_kind"), portKindName(portKind));
    if (!members.isEmpty())
        o.insert(QLatin1String("members"), QJsonArray::fromStringList(members));
    return o;
}

bool Correction::fromJson(const QJsonObject &o, Correction *correction, QString *error)
{
    Correction c;
    auto text = [&o](const char *name) { return o.value(QLatin1String(name)).toString(); };
    c.id = text("id");
    if (!kindFromName(text("kind"), &c.kind)) {
        *error = QStringLiteral("correction %1: unknown kind \"%2\"").arg(c.id, text("kind"));
        return false;
    }
    c.target = text("target");
    if (c.id.isEmpty() || c.target.isEmpty()) {
        *error = QStringLiteral("a correction needs an id and a target");
        return false;
    }
    c.oldValue = text("old");
    c.newValue = text("new");
    c.port = text("port");
    c.type = text("type");
    c.classKey = text("class");
    c.nameSpace = text("namespace");
    c.reason = text("reason");
    c.author = text("author");
    c.time = QDateTime::fromString(text("time"), Qt::ISODate);
    if (hasPortKind(c.kind) && !portKindFromName(text("port_kind"), &c.portKind)) {
        *error =
            QStringLiteral("correction %1: unknown port kind \"%2\"").arg(c.id, text("port_kind"));
        return false;
    }
    for (const QJsonValue &m : o.value(QLatin1String("members")).toArray())
        c.members << m.toString();
    *correction = c;
    return true;
}

} // namespace rosarch
