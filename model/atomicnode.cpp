#include "atomicnode.h"
#include "atomicnodelist.h"
#include "diagnostic.h"
#include "workspace.h"

#include <QDir>

namespace rosarch {

QString AtomicNode::execution() const
{
    if (!executables.isEmpty())
        return executables.first();
    if (!plugins.isEmpty())
        return plugins.first();
    return {};
}

QString compileTypeName(AtomicNode::CompileType type)
{
    return type == AtomicNode::CompileType::Python ? QStringLiteral("python") : QStringLiteral("cpp");
}

QString Diagnostic::severityName(Severity s)
{
    switch (s) {
    case Severity::Info: return QStringLiteral("info");
    case Severity::Warning: return QStringLiteral("warning");
    case Severity::Error: return QStringLiteral("error");
    }
    return {};
}

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

const AtomicNode *AtomicNodeList::node(const QString &id) const
{
    for (const AtomicNode &n : nodes)
        if (n.id == id)
            return &n;
    return nullptr;
}

QList<const AtomicNode *> AtomicNodeList::nodesOfPackage(const QString &package) const
{
    QList<const AtomicNode *> out;
    for (const AtomicNode &n : nodes)
        if (n.packageName == package)
            out.append(&n);
    return out;
}

} // namespace rosarch
