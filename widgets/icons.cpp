#include "icons.h"

#include <QHash>

namespace rosarch {

QIcon Icons::fromResource(const char *name)
{
    static QHash<QString, QIcon> cache;
    const QString path = QStringLiteral(":/icons/%1.svg").arg(QLatin1String(name));
    auto it = cache.constFind(path);
    if (it == cache.constEnd())
        it = cache.insert(path, QIcon(path));
    return *it;
}

QIcon Icons::application()
{
    return fromResource("rosarch");
}
QIcon Icons::package()
{
    return fromResource("package");
}
QIcon Icons::node()
{
    return fromResource("node");
}
QIcon Icons::diagnostics()
{
    return fromResource("diagnostics");
}
QIcon Icons::open()
{
    return fromResource("open");
}
QIcon Icons::run()
{
    return fromResource("run");
}
QIcon Icons::stop()
{
    return fromResource("stop");
}

QIcon Icons::port(PortKind kind)
{
    switch (kind) {
    case PortKind::Publisher:
        return fromResource("publisher");
    case PortKind::Subscriber:
        return fromResource("subscriber");
    case PortKind::ServiceServer:
        return fromResource("service_server");
    case PortKind::ServiceClient:
        return fromResource("service_client");
    case PortKind::ActionServer:
        return fromResource("action_server");
    case PortKind::ActionClient:
        return fromResource("action_client");
    }
    return {};
}

QIcon Icons::severity(Diagnostic::Severity severity)
{
    switch (severity) {
    case Diagnostic::Severity::Info:
        return fromResource("info");
    case Diagnostic::Severity::Warning:
        return fromResource("warning");
    case Diagnostic::Severity::Error:
        return fromResource("error");
    }
    return {};
}

} // namespace rosarch
