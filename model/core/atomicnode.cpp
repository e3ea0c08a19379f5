#include "core/atomicnode.h"

namespace rosarch {

QString AtomicNode::execution() const
{
    if (!executables.isEmpty())
        return executables.first();
    if (!plugins.isEmpty())
        return plugins.first();
    if (isPlugin())
        return qualifiedName; // pluginlib: the class a parameter file names
    return {};
}

QString compileTypeName(AtomicNode::CompileType type)
{
    return type == AtomicNode::CompileType::Python ? QStringLiteral("python")
                                                   : QStringLiteral("cpp");
}

} // namespace rosarch
