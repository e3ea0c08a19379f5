#include "nodes/cpp/cppnodenames.h"

#include "syntax/cppsyntax.h"

#include <algorithm>

namespace rosarch {

using namespace cppsyntax;

CppNodeNames::CppNodeNames(const CppClassIndex &index, const CppNameResolver &names,
                           const CppConstructions &constructions)
    : m_index(index), m_names(names), m_constructions(constructions)
{
}

// The first argument of the base-class initializer in a constructor; without one, the base's
// default constructor names the node.
QString CppNodeNames::literalName(const CppValue &value, const CppLinkContext &ctx) const
{
    using K = CppValue::Kind;
    if (value.kind == K::Literal)
        return value.literal;
    if (value.kind != K::Local && value.kind != K::Member && value.kind != K::Constant &&
        value.kind != K::Concatenation)
        return {};
    const CppResolvedName r = m_names.resolve(value, ctx);
    return r.origin == NameOrigin::Expression || r.origin == NameOrigin::Parameter ? QString()
                                                                                   : r.name;
}

// The initializer by which a class of `lineage` before `base` (a derived one) hands arguments
// to the constructor of `lineage[base]`, with the constructor it is written in (`at`); null
// when none does, or two constructors do.
const CppBaseInitializer *CppNodeNames::baseInitializer(const QList<int> &lineage, qsizetype base,
                                                        CppLinkContext *at) const
{
    const QString name = m_index.at(lineage[base]).cls->name;
    const CppBaseInitializer *found = nullptr;
    for (qsizetype d = 0; d < base; ++d) {
        for (const auto &ref : m_index.at(lineage[d]).functions) {
            if (!ref.function->isConstructor)
                continue;
            for (const CppBaseInitializer &init : ref.function->baseInitializers) {
                if (init.arguments.isEmpty() ||
                    lastSegment(withoutTemplateArguments(init.name).remove(u' ')) != name)
                    continue;
                if (found)
                    return nullptr; // constructors that disagree: the instance decides
                found = &init;
                *at = CppLinkContext{lineage[d], ref.function, ref.file, nullptr};
            }
        }
        if (found)
            return found;
    }
    return nullptr;
}

// Which argument of a constructor of node class `cls`, called with `argumentCount` arguments,
// it hands on as the node's name (`Filter(name, options) : Node(name, options)`); -1 when it
// names the node itself or its constructors disagree.
int CppNodeNames::forwardedName(int cls, int argumentCount) const
{
    const CppClassIndex::ClassInfo &info = m_index.at(cls);
    int forwarded = -2;
    for (const auto &ref : info.functions) {
        const CppFunction &ctor = *ref.function;
        if (!ctor.isConstructor || argumentCount > ctor.parameterNames.size() ||
            argumentCount < ctor.requiredParameters)
            continue;
        for (const CppBaseInitializer &init : ctor.baseInitializers) {
            const QString name = lastSegment(withoutTemplateArguments(init.name).remove(u' '));
            const bool toABase = std::any_of(
                info.cls->bases.cbegin(), info.cls->bases.cend(), [&](const QString &b) {
                    return lastSegment(withoutTemplateArguments(b).remove(u' ')) == name;
                });
            if (!toABase)
                continue;
            const int index = init.firstArgument.kind == CppValue::Kind::FunctionParameter
                                  ? init.firstArgument.index
                                  : -1;
            if (forwarded != -2 && forwarded != index)
                return -1;
            forwarded = index;
        }
    }
    return forwarded < 0 ? -1 : forwarded;
}

QString CppNodeNames::nodeNameOf(int index, int depth) const
{
    const CppClassIndex::ClassInfo &info = m_index.at(index);
    QStringList baseNames;
    for (const QString &b : info.cls->bases)
        baseNames << withoutTemplateArguments(b).remove(u' ') << lastSegment(b);
    QString fallback;
    for (const auto &ref : info.functions) {
        if (!ref.function->isConstructor)
            continue;
        for (const CppBaseInitializer &init : ref.function->baseInitializers) {
            const QString name = withoutTemplateArguments(init.name).remove(u' ');
            if (!baseNames.contains(name) && !baseNames.contains(lastSegment(name)))
                continue;
            // A base of the workspace decides which of its arguments names the node
            // (`TestActionServer("assisted_teleop")` is an action's name, not the node's).
            CppValue named = init.firstArgument;
            for (int b : info.projectBases) {
                if (m_index.at(b).cls->name != lastSegment(name) || init.arguments.isEmpty())
                    continue;
                const int forwarded = forwardedName(b, int(init.arguments.size()));
                named = forwarded >= 0 ? init.arguments.value(forwarded) : CppValue();
            }
            if (named.kind == CppValue::Kind::Literal)
                return named.literal;
            // A constant, a member or a local holding a literal names the node; a constructor
            // parameter (`node_name`, `options`) is the instance's to decide: no name here, never
            // the parameter's own name.
            if (fallback.isEmpty() && !named.isNone())
                fallback = literalName(named, {index, ref.function, ref.file, nullptr});
            break;
        }
    }
    if (!fallback.isEmpty() || depth > kMaxLinkDepth)
        return fallback;
    for (int b : info.projectBases) {
        if (!m_index.at(b).node)
            continue;
        // `ImuForward() : PassStage(Settings{.node_name = "imu_forward"}, options)`: the name
        // the base's constructor makes of what this class hands it
        CppLinkContext at;
        if (const CppBaseInitializer *init = baseInitializer({index, b}, 1, &at)) {
            CppInstantiation inst;
            inst.className = init->name;
            inst.arguments = init->arguments;
            const QString name = m_constructions.child(b, inst, at, QString()).nodeName;
            if (!name.isEmpty() && !name.contains(u'{'))
                return name;
        }
        return nodeNameOf(b, depth + 1);
    }
    return {};
}

} // namespace rosarch
