#include "widgets/icons.h"

#include <QGuiApplication>
#include <QHash>
#include <QTimer>

#include <functional>
#include <memory>

#include <mutex>

// Resources of a static library must be registered explicitly; outside any namespace.
static void initIconResources()
{
    static std::once_flag once;
    std::call_once(once, [] { Q_INIT_RESOURCE(resources); });
}

namespace rosarch {

QIcon Icons::fromResource(const char *name)
{
    initIconResources();
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
QIcon Icons::runLaunch()
{
    return fromResource("run_launch");
}
QIcon Icons::launchArguments()
{
    return fromResource("launch_arguments");
}
QIcon Icons::launchFile()
{
    return fromResource("launch_file");
}
QIcon Icons::include()
{
    return fromResource("include");
}
QIcon Icons::externalInclude()
{
    return fromResource("external");
}
QIcon Icons::nodeInstance()
{
    return fromResource("node_instance");
}
QIcon Icons::nameSpace()
{
    return fromResource("namespace");
}
QIcon Icons::container()
{
    return fromResource("container");
}
QIcon Icons::composable()
{
    return fromResource("composable");
}
QIcon Icons::unresolved()
{
    return fromResource("unresolved");
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

QIcon Icons::accepted()
{
    return fromResource("accepted");
}

void Icons::warmUp(QObject *context)
{
    using Make = std::function<QIcon()>;
    static const QList<Make> icons = {
        &Icons::package,
        &Icons::node,
        &Icons::launchFile,
        &Icons::include,
        &Icons::externalInclude,
        &Icons::nodeInstance,
        &Icons::nameSpace,
        &Icons::container,
        &Icons::composable,
        &Icons::unresolved,
        [] { return Icons::port(PortKind::Publisher); },
        [] { return Icons::port(PortKind::Subscriber); },
        [] { return Icons::port(PortKind::ServiceServer); },
        [] { return Icons::port(PortKind::ServiceClient); },
        [] { return Icons::port(PortKind::ActionServer); },
        [] { return Icons::port(PortKind::ActionClient); },
        [] { return Icons::severity(Diagnostic::Severity::Info); },
        [] { return Icons::severity(Diagnostic::Severity::Warning); },
        [] { return Icons::severity(Diagnostic::Severity::Error); },
        [] { return Icons::accepted(); },
    };
    auto *timer = new QTimer(context);
    timer->setInterval(0);
    auto next = std::make_shared<qsizetype>(0);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, next] {
        if (*next >= icons.size()) {
            timer->deleteLater();
            return;
        }
        const QIcon icon = icons.at((*next)++)();
        const qreal ratio = qApp->devicePixelRatio();
        icon.pixmap(QSize(16, 16), ratio, QIcon::Normal);
        icon.pixmap(QSize(16, 16), ratio, QIcon::Disabled);
    });
    timer->start();
}

} // namespace rosarch
