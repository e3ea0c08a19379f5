#pragma once

#include "core/diagnostic.h"
#include "core/port.h"

#include <QIcon>
#include <QObject>

namespace rosarch {

/// The icons of the views (from this library's resources, `:/icons/`), cached.
class Icons
{
public:
    static QIcon application();
    static QIcon package();
    static QIcon node();
    static QIcon port(PortKind kind);
    static QIcon severity(Diagnostic::Severity severity);
    /// A finding a person accepted (a green tick).
    static QIcon accepted();
    static QIcon diagnostics();
    static QIcon open();
    static QIcon run();
    static QIcon stop();
    static QIcon runLaunch();
    static QIcon launchArguments();

    // Launch tree
    static QIcon launchFile();
    static QIcon include();
    static QIcon externalInclude();
    static QIcon nodeInstance();
    static QIcon nameSpace();
    static QIcon container();
    static QIcon composable();
    static QIcon unresolved();

    /// Renders the views' icons (16 px, normal and greyed) one per event-loop turn while the
    /// window waits for its first result, so that painting that result does not render them:
    /// SVG icons rendered the first time cost the first paint of the trees several ms.
    static void warmUp(QObject *context);

private:
    static QIcon fromResource(const char *name);
};

} // namespace rosarch
