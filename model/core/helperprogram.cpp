#include "helperprogram.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace rosarch {

QString findHelperProgram(const QString &configured, const char *environment, const QString &name,
                          const QString &buildTree)
{
    if (!configured.isEmpty())
        return configured;
    const QString fromEnvironment = qEnvironmentVariable(environment);
    if (!fromEnvironment.isEmpty())
        return fromEnvironment;
    if (QCoreApplication::instance()) {
        const QString beside = QDir(QCoreApplication::applicationDirPath()).filePath(name);
        if (QFileInfo(beside).isExecutable())
            return beside;
    }
    if (!buildTree.isEmpty() && QFileInfo(buildTree).isExecutable())
        return buildTree;
    return {};
}

} // namespace rosarch
