#include "nodes/cpp/cppnameresolver.h"

#include "syntax/cppsyntax.h"

// Types for the linker: an interface type as written, through the aliases in scope.
namespace rosarch {

using namespace cppsyntax;

QString CppNameResolver::resolveType(const QString &written, const CppLinkContext &ctx) const
{
    return written.isEmpty() ? written : canonicalInterfaceType(expandAliases(written, ctx));
}

// Replaces the first segment through the aliases visible from `ctx` (function, class and its
// bases, file, helper template arguments, then interface typedefs of the package).
QString CppNameResolver::expandAliases(const QString &written, const CppLinkContext &ctx) const
{
    QList<const QHash<QString, QString> *> scopes;
    if (ctx.subst && !ctx.subst->templateArguments.isEmpty())
        scopes.append(&ctx.subst->templateArguments);
    if (ctx.fn)
        scopes.append(&ctx.fn->aliases);
    if (ctx.cls >= 0)
        for (int c : m_index.lineage(ctx.cls))
            scopes.append(&m_index.at(c).cls->aliases);
    if (ctx.file)
        scopes.append(&ctx.file->aliases);
    if (ctx.cls >= 0)
        scopes.append(&m_index.at(ctx.cls).file->aliases);
    const QString package = ctx.file ? ctx.file->package : QString();
    for (const QString &scope : {package, QString()}) {
        const auto it = m_interfaceAliases.constFind(scope);
        if (it != m_interfaceAliases.constEnd())
            scopes.append(&*it);
    }
    QString type = written.trimmed();
    if (type.startsWith(QLatin1String("typename ")))
        type = type.mid(9);
    for (int step = 0; step < kMaxLinkDepth; ++step) {
        QStringList parts = splitScope(type);
        if (parts.isEmpty())
            break;
        const QString head = parts.first();
        QString target;
        for (const auto *aliases : std::as_const(scopes)) {
            target = aliases->value(head);
            if (!target.isEmpty())
                break;
        }
        if (target.isEmpty() || target == head)
            break;
        parts[0] = target;
        type = parts.join(QStringLiteral("::"));
    }
    return type;
}

QStringList CppNameResolver::scopeOf(const CppLinkContext &ctx) const
{
    if (ctx.cls >= 0) {
        const CppClass &c = *m_index.at(ctx.cls).cls;
        return c.scope + QStringList{c.name};
    }
    return ctx.fn ? ctx.fn->namespaces : QStringList();
}

} // namespace rosarch
