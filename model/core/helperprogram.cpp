#include "core/helperprogram.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

// ROSARCH_HELPERS_FROM_BIN and ROSARCH_DATA_FROM_BIN are the install layout, as paths relative
// to the installed executable (cmake/RosarchInstallDirs.cmake).

namespace rosarch {

QString findHelperProgram(const QString &configured, const char *environment, const QString &name)
{
    if (!configured.isEmpty())
        return configured;
    const QString fromEnvironment = qEnvironmentVariable(environment);
    if (!fromEnvironment.isEmpty())
        return fromEnvironment;
    if (!QCoreApplication::instance())
        return {};
    // No compiled-in build-tree path: the same binary runs from the build tree, from an
    // install prefix and from wherever that prefix is moved to.
    const QDir app(QCoreApplication::applicationDirPath());
    for (const QString &candidate :
         {app.filePath(name), app.filePath(QStringLiteral(ROSARCH_HELPERS_FROM_BIN "/") + name)}) {
        if (QFileInfo(candidate).isExecutable())
            return QDir::cleanPath(candidate);
    }
    return {};
}

QString findInstalledData(const QString &relative)
{
    if (!QCoreApplication::instance())
        return {};
    const QDir app(QCoreApplication::applicationDirPath());
    const QString path =
        QDir::cleanPath(app.filePath(QStringLiteral(ROSARCH_DATA_FROM_BIN "/") + relative));
    return QFileInfo::exists(path) ? path : QString();
}

} // namespace rosarch
