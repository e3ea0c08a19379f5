#include "cppnodelinker.h"

#include "cppsyntax.h"

// Name and type resolution for the linker: port names through members, locals and declared
// parameters, helper constructor arguments, guards, and interface types through aliases.
namespace rosarch {

using namespace cppsyntax;

CppNodeLinker::Resolved CppNodeLinker::resolve(const CppValue &value, const Context &ctx,
                                               int depth) const
{
    Resolved r;
    r.name = value.text;
    r.expression = value.text;
    switch (value.kind) {
    case CppValue::Kind::Literal:
        return {NameOrigin::Literal, value.literal, QString(), QString()};
    case CppValue::Kind::Local:
        return {NameOrigin::Local, value.literal, value.text, QString()};
    case CppValue::Kind::Parameter: {
        const QString def = parameterDefault(value.parameter, ctx, depth + 1);
        return {NameOrigin::Parameter, def.isNull() ? value.text : def, value.text,
                value.parameter};
    }
    case CppValue::Kind::Member:
        return resolveMember(value.variable, value.text, ctx, depth + 1);
    case CppValue::Kind::FunctionParameter:
        if (substitutes(ctx) && depth < kMaxDepth) {
            if (value.index >= 0 && value.index < ctx.subst->arguments.size())
                return resolve(ctx.subst->arguments.at(value.index), ctx.subst->outer, depth + 1);
            const QString def = ctx.fn->parameterDefaults.value(value.index);
            if (!def.isEmpty())
                return {NameOrigin::Literal, def, QString(), QString()};
        }
        return r;
    default:
        return r;
    }
}

CppNodeLinker::Resolved CppNodeLinker::resolveMember(const QString &member, const QString &text,
                                                     const Context &ctx, int depth) const
{
    Resolved expression{NameOrigin::Expression, text, text, QString()};
    if (depth > kMaxDepth)
        return expression;
    if (ctx.cls >= 0) {
        for (int c : m_index.lineage(ctx.cls)) {
            const QList<Binding> bindings = facts(c).bindings.value(member);
            if (bindings.isEmpty())
                continue;
            for (const Binding &b : bindings) {
                if (b.value.kind == CppValue::Kind::Parameter) {
                    const QString def = parameterDefault(b.value.parameter, ctx, depth + 1);
                    return {NameOrigin::Parameter, def.isNull() ? text : def, text,
                            b.value.parameter};
                }
            }
            for (const Binding &b : bindings) {
                if ((b.value.kind == CppValue::Kind::Literal ||
                     b.value.kind == CppValue::Kind::Local) &&
                    !b.value.literal.isEmpty())
                    return {NameOrigin::Member, b.value.literal, text, QString()};
            }
            for (const Binding &b : bindings) {
                Resolved r;
                if (b.value.kind == CppValue::Kind::FunctionParameter && ctx.subst && b.fn) {
                    r = resolve(b.value, Context{ctx.cls, b.fn, b.file, ctx.subst}, depth + 1);
                } else if (b.value.kind == CppValue::Kind::Member && b.value.variable != member) {
                    r = resolveMember(b.value.variable, text, ctx, depth + 1);
                } else {
                    continue;
                }
                if (r.origin != NameOrigin::Expression)
                    return r;
            }
            return expression;
        }
    }
    for (const CppFileFacts *file : {ctx.file, ctx.cls >= 0 ? m_index.at(ctx.cls).file : nullptr}) {
        if (file && file->constants.contains(member))
            return {NameOrigin::Local, file->constants.value(member), text, QString()};
    }
    return expression;
}

QString CppNodeLinker::parameterDefault(const QString &parameter, const Context &ctx,
                                        int depth) const
{
    const CppParameterDeclaration *decl = nullptr;
    Context declared = ctx;
    if (ctx.fn)
        for (const CppParameterDeclaration &d : ctx.fn->parameterDeclarations)
            if (!decl && d.parameter == parameter)
                decl = &d;
    if (!decl && ctx.cls >= 0) {
        for (int c : m_index.lineage(ctx.cls)) {
            const MemberFacts &f = facts(c);
            const auto it = f.parameters.constFind(parameter);
            if (it != f.parameters.constEnd()) {
                decl = &*it;
                break;
            }
        }
    }
    if (!decl)
        return QString();
    const CppValue &v = decl->defaultValue;
    switch (v.kind) {
    case CppValue::Kind::None:
        return QStringLiteral("");
    case CppValue::Kind::Literal:
    case CppValue::Kind::Local:
        return v.literal;
    case CppValue::Kind::Member:
    case CppValue::Kind::FunctionParameter: {
        if (depth > kMaxDepth)
            return v.text;
        const Resolved r = resolve(v, declared, depth + 1);
        return r.origin == NameOrigin::Expression ? v.text : r.name;
    }
    default:
        return v.text;
    }
}

QString CppNodeLinker::guardParameter(const CppValue &value, const Context &ctx) const
{
    if (value.kind == CppValue::Kind::Parameter)
        return value.parameter;
    if (value.kind == CppValue::Kind::Member) {
        const Resolved r = resolveMember(value.variable, value.text, ctx, 0);
        if (r.origin == NameOrigin::Parameter)
            return r.parameter;
    }
    return {};
}

bool CppNodeLinker::isNodeHandle(const CppValue &value, const Context &ctx, int depth) const
{
    if (depth > kMaxDepth)
        return false;
    switch (value.kind) {
    case CppValue::Kind::SelfNode:
        return true;
    case CppValue::Kind::FunctionParameter:
        if (substitutes(ctx) && value.index >= 0 && value.index < ctx.subst->arguments.size())
            return isNodeHandle(ctx.subst->arguments.at(value.index), ctx.subst->outer, depth + 1);
        return false;
    case CppValue::Kind::Member:
        if (ctx.cls < 0)
            return false;
        for (int c : m_index.lineage(ctx.cls)) {
            for (const Binding &b : facts(c).bindings.value(value.variable)) {
                if (b.value.kind == CppValue::Kind::SelfNode)
                    return true;
                if (b.value.kind == CppValue::Kind::FunctionParameter && b.fn &&
                    isNodeHandle(b.value, Context{ctx.cls, b.fn, b.file, ctx.subst}, depth + 1))
                    return true;
            }
        }
        return false;
    default:
        return false;
    }
}

QString CppNodeLinker::resolveType(const QString &written, const Context &ctx) const
{
    return written.isEmpty() ? written : canonicalInterfaceType(expandAliases(written, ctx));
}

// Replaces the first segment through the aliases visible from `ctx` (function, class and its
// bases, file, helper template arguments, then interface typedefs of the package).
QString CppNodeLinker::expandAliases(const QString &written, const Context &ctx) const
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
    for (int step = 0; step < kMaxDepth; ++step) {
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

} // namespace rosarch
