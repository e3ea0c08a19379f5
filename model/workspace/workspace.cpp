#include "workspace/workspace.h"

#include <QDir>

namespace rosarch {

QString Workspace::absolutePath(const QString &relativePath) const
{
    return QDir(root).filePath(relativePath);
}

const RosPackage *Workspace::package(const QString &name) const
{
    for (const RosPackage &p : packages)
        if (p.name == name)
            return &p;
    return nullptr;
}

} // namespace rosarch
