#include "nodes/cpp/cppconstructions.h"

#include "syntax/cppsyntax.h"

#include <QRegularExpression>

#include <algorithm>

namespace rosarch {

using namespace cppsyntax;

CppConstructions::CppConstructions(const CppClassIndex &index, const CppNameResolver &names,
                                   const CppHelperPorts &helpers)
    : m_index(index), m_names(names), m_helpers(helpers)
{
}

// A parameter's literal default, at the definition or at the declaration in the class body.
QString CppConstructions::parameterDefault(int cls, const CppFunction &fn, int index) const
{
    const QString atDefinition = fn.parameterDefaults.value(index);
    if (!atDefinition.isEmpty())
        return atDefinition;
    return m_index.at(cls).cls->declaredDefaults.value(fn.name).value(index);
}

// A child's name is the argument its constructor hands to the base-class initializer
// (`nav2::LifecycleNode(name, ...)`), or that parameter's default when the call leaves it out,
// else the name its class gives itself. A namespace argument that is the parent's own
// (`get_namespace()`) puts the child in the parent's namespace; handed to a constructor
// parameter named for a parent (`parent_namespace`), the child nests under it in a namespace of
// its own name, as nav2's child nodes do.
ChildNode CppConstructions::child(int cls, const CppInstantiation &inst, const CppLinkContext &ctx,
                                  const QString &ownName) const
{
    const CppClassIndex::ClassInfo &info = m_index.at(cls);
    ChildNode out;
    out.className = info.cls->qualifiedName;
    out.evidence = inst.evidence;
    out.nodeName = ownName;
    const auto argumentText = [&](int i) -> QString {
        const CppValue &arg = inst.arguments.at(i);
        if (arg.kind == CppValue::Kind::Literal ||
            (arg.kind == CppValue::Kind::Local && !arg.literal.isEmpty()))
            return arg.literal;
        const CppResolvedName r = m_names.resolve(arg, ctx);
        return r.origin == NameOrigin::Literal || r.origin == NameOrigin::Member ||
                       r.origin == NameOrigin::Local
                   ? r.name
                   : QString();
    };
    // The constructor called: of those that take every argument, the one whose string
    // parameters meet the string arguments best, then the one with the fewest parameters
    // (defaults may be written only at the declaration, out of sight of the definition).
    const auto argumentCount = int(inst.arguments.size());
    const auto fit = [&](const CppFunction &ctor) {
        int score = 0;
        for (int i = 0; i < argumentCount; ++i) {
            const CppValue &arg = inst.arguments.at(i);
            const bool text = arg.kind == CppValue::Kind::Literal ||
                              (arg.kind == CppValue::Kind::Local && !arg.literal.isEmpty());
            const QString type = ctor.parameterTypes.value(i);
            score += text == (type.contains(QLatin1String("string")) ||
                              type.contains(QLatin1String("char")));
        }
        return std::pair{score, -int(ctor.parameterNames.size())};
    };
    const CppFunction *called = nullptr;
    const CppFileFacts *calledFile = nullptr;
    for (const auto &ref : info.functions) {
        const CppFunction &ctor = *ref.function;
        if (ctor.isConstructor && argumentCount <= ctor.parameterNames.size() &&
            (!called || fit(ctor) > fit(*called))) {
            called = &ctor;
            calledFile = ref.file;
        }
    }
    if (!called)
        return out;
    // Of the initializers, those of a base class (not `topic_name_(topic_name)`).
    const auto isBase = [&](const QString &initialized) {
        const QString name = lastSegment(withoutTemplateArguments(initialized).remove(u' '));
        return std::any_of(info.cls->bases.cbegin(), info.cls->bases.cend(), [&](const QString &b) {
            return lastSegment(withoutTemplateArguments(b).remove(u' ')) == name;
        });
    };
    for (const CppBaseInitializer &init : called->baseInitializers) {
        const CppValue::Kind kind = init.firstArgument.kind;
        if ((kind == CppValue::Kind::Field || kind == CppValue::Kind::Concatenation) &&
            isBase(init.name)) {
            // `rclcpp::Node(settings.node_name, options)`, `rclcpp::Node(zone + "_watcher")`:
            // decided by the arguments of this construction
            const CppSubstitution subst{inst.arguments, ctx, {}, nullptr};
            const CppResolvedName r = m_names.resolve(
                init.firstArgument, CppLinkContext{cls, called, calledFile, &subst});
            if (r.origin == NameOrigin::Literal && !r.name.isEmpty())
                out.nodeName = r.name;
            continue;
        }
        if (init.firstArgument.kind != CppValue::Kind::FunctionParameter ||
            init.firstArgument.index < 0 || !isBase(init.name))
            continue;
        if (init.firstArgument.index < argumentCount)
            out.nodeName = argumentText(init.firstArgument.index);
        else if (const QString def = parameterDefault(cls, *called, init.firstArgument.index);
                 !def.isEmpty())
            out.nodeName = def;
    }
    for (int i = 0; i < argumentCount; ++i) {
        const QString parameter = called->parameterNames.at(i).toLower();
        if (!parameter.contains(QLatin1String("namespace")) && parameter != QLatin1String("ns"))
            continue;
        const CppValue &arg = inst.arguments.at(i);
        if (arg.text.contains(QLatin1String("get_namespace")))
            out.nameSpace = parameter.contains(QLatin1String("parent")) ? out.nodeName : QString();
        else
            out.nameSpace = argumentText(i);
    }
    return out;
}

NodeConstruction CppConstructions::construction(int cls, const CppInstantiation &inst,
                                                const CppLinkContext &ctx,
                                                const QString &ownName) const
{
    NodeConstruction out;
    out.className = inst.className;
    out.evidence = inst.evidence;
    out.guard = inst.guard;
    out.nodeName = child(cls, inst, ctx, ownName).nodeName;
    // `NodeOptions().arguments({"--ros-args", "-r", "__node:=left"})` written at the call
    // renames the node as its command line would.
    static const QRegularExpression rename(QStringLiteral("__(?:node|name):=([A-Za-z_]\\w*)"));
    for (const CppValue &arg : inst.arguments)
        if (const auto m = rename.match(arg.text); m.hasMatch())
            out.nodeName = m.captured(1);
    out.ports = m_helpers.constructedPorts(cls, inst.arguments, ctx,
                                           templateArgumentsOf(inst.className.simplified()));
    return out;
}

} // namespace rosarch
