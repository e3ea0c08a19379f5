#include "nodes/cpp/cppnameresolver.h"

#include "core/rosnames.h"
#include "syntax/cppsyntax.h"

#include <QRegularExpression>
#include <QScopeGuard>

// Name and type resolution for the linker: port names through members, locals and declared
// parameters, helper constructor arguments, guards, and interface types through aliases.
namespace rosarch {

using namespace cppsyntax;

namespace {

// `std::bind(&C::f, this, _1)` / `[this](...) {...}` / `&C::f` / `cb` as text -> callback name.
QString callbackFromText(const QString &text)
{
    const QString t = text.trimmed();
    if (t.startsWith(u'['))
        return QStringLiteral("lambda");
    static const QRegularExpression member(QStringLiteral("&\\s*([A-Za-z_][\\w:]*)"));
    const auto m = member.match(t);
    if (m.hasMatch())
        return lastSegment(m.captured(1));
    static const QRegularExpression identifier(QStringLiteral("^[A-Za-z_][\\w:]*$"));
    return identifier.match(t).hasMatch() ? lastSegment(t) : QString();
}

} // namespace

CppNameResolver::CppNameResolver(const CppClassIndex &index,
                                 const std::vector<CppMemberFacts> &facts,
                                 const QHash<QString, QHash<QString, QString>> &interfaceAliases,
                                 const CppSharedNames &shared)
    : m_index(index), m_facts(facts), m_interfaceAliases(interfaceAliases), m_shared(shared)
{
}

CppResolvedName CppNameResolver::resolve(const CppValue &value, const CppLinkContext &ctx,
                                         int depth) const
{
    CppResolvedName r;
    r.name = value.text;
    r.expression = value.text;
    switch (value.kind) {
    case CppValue::Kind::Literal:
        return {NameOrigin::Literal, value.literal, QString(), QString()};
    case CppValue::Kind::Local:
        return {NameOrigin::Local, value.literal, value.text, QString()};
    case CppValue::Kind::Parameter: {
        if (value.parameter.isEmpty())
            return resolveBuiltParameter(value, ctx, depth);
        if (value.parameter.startsWith(
                QLatin1String(RosNames::kLoadedPluginPrefix))) // per loaded plugin
            return {NameOrigin::Parameter, value.parameter, value.text, value.parameter};
        const QString def = parameterDefault(value.parameter, ctx, depth + 1);
        return {NameOrigin::Parameter, def.isNull() ? value.text : def, value.text,
                value.parameter};
    }
    case CppValue::Kind::Member:
        return resolveMember(value.variable, value.text, ctx, depth + 1);
    case CppValue::Kind::SelfCall:
        if (const CppLinkContext at = selfMethod(value.variable, ctx);
            at.fn && depth < kMaxLinkDepth)
            return resolve(at.fn->returnValue, at, depth + 1);
        if (value.variable == QLatin1String("get_name")) // rclcpp's: the instance's name
            return {NameOrigin::Member, QLatin1String(kNodeNamePlaceholder), value.text, QString()};
        if (value.variable == QLatin1String("get_namespace")) // and its namespace
            return {NameOrigin::Member, QLatin1String(RosNames::kNamespacePlaceholder), value.text,
                    QString()};
        if (value.variable == QLatin1String("get_fully_qualified_name"))
            return {NameOrigin::Member,
                    QStringLiteral("%1/%2").arg(QLatin1String(RosNames::kNamespacePlaceholder),
                                                QLatin1String(kNodeNamePlaceholder)),
                    value.text, QString()};
        return r;
    case CppValue::Kind::FunctionParameter:
        if (namesTheNode(value.index, ctx))
            return {NameOrigin::Member, QLatin1String(kNodeNamePlaceholder), value.text, QString()};
        if (const CppSubstitution *subst = substitutionFor(ctx); subst && depth < kMaxLinkDepth) {
            if (value.index >= 0 && value.index < subst->arguments.size())
                return resolve(subst->arguments.at(value.index), subst->outer, depth + 1);
            QString def = ctx.fn->parameterDefaults.value(value.index);
            if (def.isEmpty() && ctx.cls >= 0) // written where the class declares it
                def = m_index.at(ctx.cls)
                          .cls->declaredDefaults.value(ctx.fn->name)
                          .value(value.index);
            if (!def.isEmpty())
                return {NameOrigin::Literal, def, QString(), QString()};
        }
        if (isPluginNameParameter(value, ctx))
            return {NameOrigin::Member, QLatin1String(kPluginNamePlaceholder), value.text,
                    QString()};
        if (CppLinkContext caller; depth < kMaxLinkDepth && !substitutes(ctx)) {
            if (const CppValue *arg = ownCallArgument(value.index, ctx, &caller))
                return resolve(*arg, caller, depth + 1);
        }
        return r;
    case CppValue::Kind::Concatenation:
        return resolveConcatenation(value, ctx, depth);
    case CppValue::Kind::Field:
        return resolveField(value, ctx, depth + 1);
    case CppValue::Kind::Constant:
        return resolveConstant(value, ctx, depth + 1);
    case CppValue::Kind::ObjectCall: {
        // A method of the node itself, handed to a helper (`ClearCostmapService(node, *this)`).
        CppLinkContext at;
        if (depth >= kMaxLinkDepth || value.parts.empty() ||
            !nodeHandleAt(value.parts.front(), ctx, &at, depth + 1))
            return r;
        CppValue call;
        call.kind = CppValue::Kind::SelfCall;
        call.variable = value.field;
        call.text = value.text;
        at.self = at.cls;
        return resolve(call, at, depth + 1);
    }
    case CppValue::Kind::Element:
        // Each element of a list parameter (`for (auto & n : node_names_)`): one name per
        // item of the instance's value, `{node_names}` until the instance gives it.
        if (depth < kMaxLinkDepth && !value.parts.empty()) {
            const CppResolvedName list = resolve(value.parts.front(), ctx, depth + 1);
            if (list.origin == NameOrigin::Parameter && list.parameterPrefix.isEmpty() &&
                list.parameterSuffix.isEmpty() && !list.parameter.contains(u'{'))
                return {NameOrigin::Parameter, QStringLiteral("{%1}").arg(list.parameter),
                        value.text, QStringLiteral("{%1}").arg(list.parameter)};
        }
        return r;
    case CppValue::Kind::OutArgument:
        if (depth < kMaxLinkDepth) {
            const CppBinding filled = outBinding(value.variable, value.index, ctx);
            if (filled.fn) {
                CppResolvedName out = resolve(filled.value,
                                              CppLinkContext{m_index.ownerOf(filled.fn), filled.fn,
                                                             filled.file, ctx.subst, ctx.self},
                                              depth + 1);
                if (out.origin != NameOrigin::Expression)
                    out.expression = value.text; // the local, as the call reads it
                return out;
            }
        }
        return r;
    default:
        return r;
    }
}

// What `function` (of the object of `ctx`, else a free function of its file) last assigns to
// its reference parameter `index`; fn null when it assigns nothing there.
CppBinding CppNameResolver::outBinding(const QString &function, int index,
                                       const CppLinkContext &ctx) const
{
    const auto filled = [&](const CppFunction *fn, const CppFileFacts *file) -> CppBinding {
        const QString parameter = fn->parameterNames.value(index);
        for (auto it = fn->outBindings.crbegin(); it != fn->outBindings.crend(); ++it)
            if (!parameter.isEmpty() && it->member == parameter)
                return {it->value, fn, file};
        return {};
    };
    const int from = ctx.self >= 0 ? ctx.self : ctx.cls;
    if (from >= 0)
        for (int c : m_index.lineage(from))
            for (const auto &ref : m_index.at(c).functions)
                if (ref.function->name == function)
                    if (CppBinding b = filled(ref.function, ref.file); b.fn)
                        return b;
    if (ctx.file)
        for (const CppFunction &fn : ctx.file->functions)
            if (fn.name == function && fn.ownerClass < 0 && fn.ownerScope.isEmpty())
                if (CppBinding b = filled(&fn, ctx.file); b.fn)
                    return b;
    return {};
}

// A parameter whose name is built (`source_name_ + ".topic"`): decided when the name resolves
// to a literal or to a pattern over a list parameter's items (`{sources}.topic`), which the
// instance expands. The default written after the name (`parts[1]`) names the port until then;
// without one the name is empty, which only an instance's value fills.
CppResolvedName CppNameResolver::resolveBuiltParameter(const CppValue &value,
                                                       const CppLinkContext &ctx, int depth) const
{
    if (value.parts.empty() || depth > kMaxLinkDepth)
        return {NameOrigin::Expression, value.text, value.text, QString()};
    const CppResolvedName name = resolve(value.parts.front(), ctx, depth + 1);
    const bool literal = name.origin == NameOrigin::Literal;
    const bool perItem = name.origin == NameOrigin::Parameter && name.parameter.startsWith(u'{') &&
                         name.parameter.endsWith(u'}') && name.name.contains(name.parameter);
    // `name_ + "." + "map_topic"` in a plugin: the name it is loaded by fills it per instance
    const bool perPlugin = name.origin == NameOrigin::Member &&
                           name.name.contains(QLatin1String(kPluginNamePlaceholder)) &&
                           !name.name.contains(QLatin1String(kNodeNamePlaceholder));
    if ((!literal && !perItem && !perPlugin) || name.name.isEmpty())
        return {NameOrigin::Expression, value.text, value.text, QString()};
    CppResolvedName def;
    if (value.parts.size() > 1)
        def = resolve(value.parts.at(1), ctx, depth + 1);
    const bool hasDefault = def.origin == NameOrigin::Literal ||
                            (def.origin == NameOrigin::Parameter && def.name == name.parameter);
    // without a default the name is only the instance's value: empty until it is given
    return {NameOrigin::Parameter, hasDefault ? def.name : QString(), value.text, name.name};
}

// Each part resolved and joined; the whole stays the expression when a part cannot be. A part
// read from a parameter makes the whole parameter-derived.
CppResolvedName CppNameResolver::resolveConcatenation(const CppValue &value,
                                                      const CppLinkContext &ctx, int depth) const
{
    CppResolvedName whole{NameOrigin::Literal, QString(), value.text, QString()};
    if (depth > kMaxLinkDepth)
        return {NameOrigin::Expression, value.text, value.text, QString()};
    qsizetype valueAt = -1, valueSize = 0; // where the parameter's value is in the name
    for (const CppValue &part : value.parts) {
        const CppResolvedName r = resolve(part, ctx, depth + 1);
        if (r.origin == NameOrigin::Expression)
            return {NameOrigin::Expression, value.text, value.text, QString()};
        if (r.origin == NameOrigin::Parameter && whole.parameter.isEmpty()) {
            whole.origin = NameOrigin::Parameter;
            whole.parameter = r.parameter;
            valueAt = whole.name.size() + r.parameterPrefix.size();
            valueSize = r.name.size() - r.parameterPrefix.size() - r.parameterSuffix.size();
        } else if (whole.origin == NameOrigin::Literal) {
            whole.origin = r.origin;
        }
        whole.name += r.name;
    }
    if (valueAt >= 0) {
        whole.parameterPrefix = whole.name.left(valueAt);
        whole.parameterSuffix = whole.name.mid(valueAt + valueSize);
    }
    return whole;
}

// A plugin's entry point is handed its name by the loader (`configure(parent, name, ...)`,
// `initialize(..., name, ...)`): in the classifier it is the placeholder the instance fills.
bool CppNameResolver::isPluginNameParameter(const CppValue &value, const CppLinkContext &ctx) const
{
    if (ctx.self < 0 || !ctx.fn || substitutes(ctx) || ctx.fn->isConstructor)
        return false;
    static const QStringList names{QStringLiteral("name"), QStringLiteral("plugin_name"),
                                   QStringLiteral("plugin_id"), QStringLiteral("id")};
    const QString type = ctx.fn->parameterTypes.value(value.index);
    if (!names.contains(ctx.fn->parameterNames.value(value.index)) ||
        !type.contains(QLatin1String("string")))
        return false;
    for (const QString &t : ctx.fn->parameterTypes)
        if (isNodeHandleType(t))
            return true;
    return false;
}

CppResolvedName CppNameResolver::resolveMember(const QString &member, const QString &text,
                                               const CppLinkContext &ctx, int depth) const
{
    CppResolvedName expression{NameOrigin::Expression, text, text, QString()};
    if (depth > kMaxLinkDepth)
        return expression;
    // `initializeFilter(topic_)` where `initializeFilter(t)` sets `topic_ = join(t)`: the member
    // read while a class's bindings of it are being resolved is the value another class (a
    // base) gives it; those bindings are not entered again.
    thread_local QList<QPair<QString, int>> open;
    if (ctx.cls >= 0) {
        for (int c : m_index.lineage(ctx.cls)) {
            const QList<CppBinding> bindings = facts(c).bindings.value(member);
            if (bindings.isEmpty() || open.contains(qMakePair(member, c)))
                continue;
            open.append(qMakePair(member, c));
            const auto close = qScopeGuard([] { open.removeLast(); });
            // `name_(name)` beside `LifecycleNode(name, ...)` in every constructor: the node's
            // own name, whichever constructor made it.
            if (std::all_of(bindings.cbegin(), bindings.cend(),
                            [&](const CppBinding &b) { return holdsTheNodeName(b, c); }))
                return {NameOrigin::Member, QLatin1String(kNodeNamePlaceholder), text, QString()};
            // `map_topic_ = joinWithParentNamespace(map_topic_)`: the value passes through a
            // function that is not followed, so no earlier value is the name.
            const QRegularExpression self(
                QStringLiteral("\\b%1\\b").arg(QRegularExpression::escape(member)));
            if (std::any_of(bindings.cbegin(), bindings.cend(), [&](const CppBinding &b) {
                    return b.value.kind == CppValue::Kind::Expression &&
                           b.value.text.contains(self);
                }))
                return expression;
            for (const CppBinding &b : bindings) {
                if (b.value.kind == CppValue::Kind::Parameter && b.value.parameter.isEmpty()) {
                    // a name built at run time, decided when its parts are
                    const CppResolvedName r =
                        b.fn ? resolve(b.value,
                                       CppLinkContext{ctx.cls, b.fn, b.file, ctx.subst, ctx.self},
                                       depth + 1)
                             : CppResolvedName();
                    return r.origin == NameOrigin::Expression ? expression : r;
                }
                if (b.value.kind == CppValue::Kind::Parameter) {
                    const QString def = parameterDefault(b.value.parameter, ctx, depth + 1);
                    return {NameOrigin::Parameter, def.isNull() ? text : def, text,
                            b.value.parameter};
                }
            }
            for (const CppBinding &b : bindings) {
                if ((b.value.kind == CppValue::Kind::Literal ||
                     b.value.kind == CppValue::Kind::Local) &&
                    !b.value.literal.isEmpty())
                    return {NameOrigin::Member, b.value.literal, text, QString()};
            }
            for (const CppBinding &b : bindings) {
                CppResolvedName r;
                const bool composed = b.value.kind == CppValue::Kind::Concatenation ||
                                      b.value.kind == CppValue::Kind::SelfCall;
                if ((b.value.kind == CppValue::Kind::FunctionParameter && b.fn) ||
                    (composed && b.fn)) {
                    r = resolve(b.value, CppLinkContext{ctx.cls, b.fn, b.file, ctx.subst, ctx.self},
                                depth + 1);
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
    // A constant of an included header, in this package or another.
    if (const QString c = m_shared.constant(member, packageOf(ctx)); !c.isNull())
        return {NameOrigin::Local, c, text, QString()};
    return expression;
}

// A field of a parameters struct: the parameter the workspace reads into it, found by the
// object's struct type or, when one side's type is unknown, by the field's name within the
// package; else the struct's own in-class initializer.
CppResolvedName CppNameResolver::resolveField(const CppValue &value, const CppLinkContext &ctx,
                                              int depth) const
{
    const QString &text = value.text;
    CppResolvedName expression{NameOrigin::Expression, text, text, QString()};
    if (depth > kMaxLinkDepth)
        return expression;
    // `settings.topic` of a parameter the caller hands `Settings{.topic = "scan"}`
    if (const CppSubstitution *subst = substitutionFor(ctx);
        subst && value.index >= 0 && value.index < subst->arguments.size()) {
        const CppValue &arg = subst->arguments.at(value.index);
        for (size_t i = 0; arg.kind == CppValue::Kind::Aggregate && i + 1 < arg.parts.size();
             i += 2)
            if (arg.parts[i].literal == value.field)
                return resolve(arg.parts[i + 1], subst->outer, depth + 1);
    }
    QString written = value.objectType;
    QStringList templateParameters;
    if (written.isEmpty() && !value.variable.isEmpty() && ctx.cls >= 0)
        written = m_shared.memberType(value.variable, ctx.cls, &templateParameters);
    const QString type = CppSharedNames::structType(written, templateParameters);
    const CppSharedNames::FieldBinding *read = nullptr;
    for (const CppSharedNames::FieldBinding *b :
         m_shared.fieldBindings(value.field, type, packageOf(ctx))) {
        if (read && read->value.parameter != b->value.parameter)
            return expression; // two structs' fields of one name, filled differently
        read = b;
    }
    if (read && read->value.parameter.isEmpty()) // a name built at run time
        return expression;
    if (read) {
        const CppLinkContext at{read->cls, read->fn, read->file, nullptr, -1};
        const QString def = parameterDefault(read->value.parameter, at, depth + 1);
        return {NameOrigin::Parameter, def.isNull() ? text : def, text, read->value.parameter};
    }
    const int cls = type.isEmpty() ? -1 : m_index.lookup(type, scopeOf(ctx), ctx.file);
    if (cls < 0 || m_index.at(cls).cls->name != type)
        return expression;
    const CppResolvedName r = resolveMember(
        value.field, text, CppLinkContext{cls, nullptr, m_index.at(cls).file}, depth + 1);
    return r.origin == NameOrigin::Parameter || r.origin == NameOrigin::Member ? r : expression;
}

// `ns::kTopic` names a namespace-level constant; `Foo::kTopic` a class's static member.
CppResolvedName CppNameResolver::resolveConstant(const CppValue &value, const CppLinkContext &ctx,
                                                 int depth) const
{
    CppResolvedName expression{NameOrigin::Expression, value.text, value.text, QString()};
    const QStringList parts = splitScope(value.variable);
    if (parts.size() < 2 || depth > kMaxLinkDepth)
        return expression;
    const QString &name = parts.last();
    const QString scope = parts.mid(0, parts.size() - 1).join(QStringLiteral("::"));
    const int cls = m_index.lookup(scope, scopeOf(ctx), ctx.file);
    if (cls >= 0)
        return resolveMember(name, value.text, CppLinkContext{cls, nullptr, m_index.at(cls).file},
                             depth + 1);
    return resolveMember(name, value.text, CppLinkContext{-1, ctx.fn, ctx.file, nullptr, -1},
                         depth + 1);
}

QString CppNameResolver::packageOf(const CppLinkContext &ctx) const
{
    if (ctx.file)
        return ctx.file->package;
    return ctx.cls >= 0 ? m_index.at(ctx.cls).file->package : QString();
}

QString CppNameResolver::parameterDefault(const QString &parameter, const CppLinkContext &ctx,
                                          int depth) const
{
    const CppParameterDeclaration *decl = nullptr;
    CppLinkContext declared = ctx;
    if (ctx.fn)
        for (const CppParameterDeclaration &d : ctx.fn->parameterDeclarations)
            if (!decl && !d.parameter.isEmpty() && d.parameter == parameter)
                decl = &d;
    if (!decl && ctx.cls >= 0) {
        for (int c : m_index.lineage(ctx.cls)) {
            const CppMemberFacts &f = facts(c);
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
        if (depth > kMaxLinkDepth)
            return v.text;
        const CppResolvedName r = resolve(v, declared, depth + 1);
        return r.origin == NameOrigin::Expression ? v.text : r.name;
    }
    default: {
        // A constant holding a literal is the default; anything else (an expression, an enum
        // such as rclcpp::ParameterType::PARAMETER_STRING, which declares no default) is none:
        // never C++ text as a name.
        if (depth > kMaxLinkDepth)
            return QString();
        const CppResolvedName r = resolve(v, declared, depth + 1);
        return r.origin == NameOrigin::Expression ? QString() : r.name;
    }
    }
}

QString CppNameResolver::guardParameter(const CppValue &value, const CppLinkContext &ctx) const
{
    if (value.kind == CppValue::Kind::Parameter && value.parameter.isEmpty()) {
        const CppResolvedName r = resolveBuiltParameter(value, ctx, 0); // `{sources}.type`
        return r.origin == NameOrigin::Parameter ? r.parameter : QString();
    }
    if (value.kind == CppValue::Kind::Parameter)
        return value.parameter;
    if (value.kind == CppValue::Kind::Member || value.kind == CppValue::Kind::Field) {
        const CppResolvedName r = value.kind == CppValue::Kind::Member
                                      ? resolveMember(value.variable, value.text, ctx, 0)
                                      : resolveField(value, ctx, 0);
        if (r.origin == NameOrigin::Parameter)
            return r.parameter;
    }
    return {};
}

// A node class's constructor parameter that it hands its base class as the node's name
// (`Costmap2DROS(name, ...) : LifecycleNode(name, ...), name_(name)`): where the class is not
// constructed with known arguments, it is the instance's own name.
bool CppNameResolver::namesTheNode(int index, const CppLinkContext &ctx) const
{
    if (!ctx.fn || !ctx.fn->isConstructor || substitutes(ctx) || ctx.cls < 0 || index < 0 ||
        !m_index.at(ctx.cls).node)
        return false;
    for (const CppBaseInitializer &init : ctx.fn->baseInitializers)
        if (init.firstArgument.kind == CppValue::Kind::FunctionParameter &&
            init.firstArgument.index == index && lastSegment(init.name).contains(u"Node"))
            return true;
    return false;
}

// A member's binding in a constructor of node class `cls` that stores the name the constructor
// hands its base class: the same parameter, or the same literal.
bool CppNameResolver::holdsTheNodeName(const CppBinding &b, int cls) const
{
    if (!b.fn || !b.fn->isConstructor)
        return false;
    if (b.value.kind == CppValue::Kind::FunctionParameter)
        return namesTheNode(b.value.index, CppLinkContext{cls, b.fn, b.file});
    if (b.value.kind != CppValue::Kind::Literal || b.value.literal.isEmpty() ||
        !m_index.at(cls).node)
        return false;
    for (const CppBaseInitializer &init : b.fn->baseInitializers)
        if (init.firstArgument.kind == CppValue::Kind::Literal &&
            init.firstArgument.literal == b.value.literal &&
            lastSegment(init.name).contains(u"Node"))
            return true;
    return false;
}

bool CppNameResolver::isNodeHandle(const CppValue &value, const CppLinkContext &ctx,
                                   int depth) const
{
    CppLinkContext unused;
    return nodeHandleAt(value, ctx, &unused, depth);
}

bool CppNameResolver::nodeHandleAt(const CppValue &value, const CppLinkContext &ctx,
                                   CppLinkContext *at, int depth) const
{
    if (depth > kMaxLinkDepth)
        return false;
    switch (value.kind) {
    case CppValue::Kind::SelfNode:
        *at = ctx;
        return true;
    case CppValue::Kind::FunctionParameter:
        if (const CppSubstitution *subst = substitutionFor(ctx);
            subst && value.index >= 0 && value.index < subst->arguments.size())
            return nodeHandleAt(subst->arguments.at(value.index), subst->outer, at, depth + 1);
        // A plugin's `configure(parent_node, ...)`: a parameter typed as a node handle.
        return ctx.subst && ctx.subst->plugin && !substitutes(ctx) && ctx.fn &&
               isNodeHandleType(ctx.fn->parameterTypes.value(value.index));
    case CppValue::Kind::Member:
        if (ctx.cls < 0)
            return false;
        for (int c : m_index.lineage(ctx.cls)) {
            for (const CppBinding &b : facts(c).bindings.value(value.variable)) {
                if (b.value.kind == CppValue::Kind::SelfNode) {
                    *at = ctx;
                    return true;
                }
                if (b.value.kind == CppValue::Kind::FunctionParameter && b.fn &&
                    nodeHandleAt(b.value,
                                 CppLinkContext{ctx.cls, b.fn, b.file, ctx.subst, ctx.self}, at,
                                 depth + 1))
                    return true;
            }
        }
        return false;
    default:
        return false;
    }
}

CppLinkContext CppNameResolver::selfMethod(const QString &name, const CppLinkContext &ctx) const
{
    const int from = ctx.self >= 0 ? ctx.self : ctx.cls;
    if (from < 0)
        return {};
    for (int c : m_index.lineage(from))
        for (const auto &ref : m_index.at(c).functions)
            if (ref.function->name == name && ref.function->parameterNames.isEmpty() &&
                !ref.function->returnValue.isNone())
                return CppLinkContext{c, ref.function, ref.file, ctx.subst, ctx.self};
    return {};
}

bool isNodeHandleType(const QString &type)
{
    static const QRegularExpression node(
        QStringLiteral("(^|::|<|\\s)(Node|LifecycleNode|LifecycleNodeInterface)(\\s*(::(WeakPtr|"
                       "SharedPtr|Ptr)|>|\\*|&)|$)"));
    return node.match(type.simplified()).hasMatch();
}

const CppMemberFacts &CppNameResolver::facts(int cls) const
{
    return m_facts[size_t(cls)];
}

Port CppNameResolver::port(const CppPortCall &call, const CppLinkContext &ctx) const
{
    Port port;
    port.kind = call.kind;
    const CppResolvedName r = resolve(call.name, ctx);
    port.name = r.name;
    port.nameOrigin = r.origin;
    port.nameExpression = r.expression;
    port.parameter = r.parameter;
    port.parameterPrefix = r.parameterPrefix;
    port.parameterSuffix = r.parameterSuffix;
    port.type =
        !call.transportType.isEmpty() ? call.transportType : resolveType(call.typeWritten, ctx);
    port.callback = call.callback;
    const CppSubstitution *subst = substitutionFor(ctx);
    if (call.callbackParameter >= 0 && subst && call.callbackParameter < subst->arguments.size()) {
        const QString handed = callbackFromText(subst->arguments.at(call.callbackParameter).text);
        if (!handed.isEmpty())
            port.callback = handed;
    }
    port.qos = call.qos;
    port.guard = call.guard;
    port.guardParameter = guardParameter(call.guardValue, ctx);
    if (!port.guardParameter.isEmpty())
        port.guardDefault = parameterDefault(port.guardParameter, ctx, 0);
    port.evidence = call.evidence;
    return port;
}

} // namespace rosarch
