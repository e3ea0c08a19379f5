#include "core/port.h"

#include <QRegularExpression>

#include <array>
#include <utility>

namespace rosarch {

namespace {
constexpr std::array<std::pair<PortKind, const char *>, 6> kKindNames{{
    {PortKind::Publisher, "publisher"},
    {PortKind::Subscriber, "subscriber"},
    {PortKind::ServiceServer, "service_server"},
    {PortKind::ServiceClient, "service_client"},
    {PortKind::ActionServer, "action_server"},
    {PortKind::ActionClient, "action_client"},
}};
} // namespace

bool isCanonicalInterfaceType(const QString &type)
{
    static const QRegularExpression canonical(
        QStringLiteral("^[A-Za-z][A-Za-z0-9_]*/(msg|srv|action)/[A-Za-z][A-Za-z0-9_]*$"));
    return canonical.match(type).hasMatch();
}

QString portKindName(PortKind kind)
{
    for (const auto &[k, name] : kKindNames)
        if (k == kind)
            return QString::fromLatin1(name);
    return {};
}

bool portKindFromName(const QString &name, PortKind *kind)
{
    for (const auto &[k, n] : kKindNames) {
        if (name == QLatin1String(n)) {
            *kind = k;
            return true;
        }
    }
    return false;
}

QString portFamilyName(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
    case PortKind::Subscriber:
        return QStringLiteral("topic");
    case PortKind::ServiceServer:
    case PortKind::ServiceClient:
        return QStringLiteral("service");
    case PortKind::ActionServer:
    case PortKind::ActionClient:
        break;
    }
    return QStringLiteral("action");
}

QString portIdPrefix(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return QStringLiteral("p");
    case PortKind::Subscriber:
        return QStringLiteral("s");
    case PortKind::ServiceServer:
        return QStringLiteral("ps");
    case PortKind::ServiceClient:
        return QStringLiteral("rs");
    case PortKind::ActionServer:
        return QStringLiteral("pa");
    case PortKind::ActionClient:
        return QStringLiteral("ra");
    }
    return {};
}

QString nameOriginName(NameOrigin origin)
{
    switch (origin) {
    case NameOrigin::Literal:
        return QStringLiteral("literal");
    case NameOrigin::Member:
        return QStringLiteral("member");
    case NameOrigin::Local:
        return QStringLiteral("local");
    case NameOrigin::Parameter:
        return QStringLiteral("parameter");
    case NameOrigin::Expression:
        return QStringLiteral("expression");
    }
    return {};
}

bool isInputPort(PortKind kind)
{
    return kind == PortKind::Subscriber || kind == PortKind::ServiceServer ||
           kind == PortKind::ActionServer;
}

bool isProvidingPort(PortKind kind)
{
    return kind == PortKind::Publisher || kind == PortKind::ServiceServer ||
           kind == PortKind::ActionServer;
}

} // namespace rosarch
