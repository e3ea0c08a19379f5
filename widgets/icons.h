#pragma once

#include "diagnostic.h"
#include "port.h"

#include <QIcon>

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

private:
    static QIcon fromResource(const char *name);
};

} // namespace rosarch
