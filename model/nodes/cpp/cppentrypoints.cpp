#include "nodes/cpp/cppentrypoints.h"

#include "syntax/cppsyntax.h"

#include <algorithm>

namespace rosarch {

using namespace cppsyntax;

namespace {

// A node built in a loop over a list of names (`for (const auto & zone : zones)`, `zones`
// holding literals): one construction per item, the loop variable an item's literal in each.
QList<CppInstantiation> perListItem(const CppInstantiation &inst)
{
    constexpr size_t kMaxItems = 64; // a list written out in code; more is no list of names
    for (qsizetype a = 0; a < inst.arguments.size(); ++a) {
        const CppValue &arg = inst.arguments.at(a);
        if (arg.kind != CppValue::Kind::Element || arg.parts.empty())
            continue;
        const CppValue &list = arg.parts.front();
        if (list.kind != CppValue::Kind::Aggregate || list.parts.size() > 2 * kMaxItems)
            continue;
        QList<CppInstantiation> out;
        for (size_t i = 0; i + 1 < list.parts.size(); i += 2) {
            if (!list.parts[i].literal.isEmpty() ||
                list.parts[i + 1].kind != CppValue::Kind::Literal)
                return {inst}; // a struct's fields, or an item that is no literal
            CppInstantiation one = inst;
            one.arguments[a] = list.parts[i + 1];
            out.append(one);
        }
        if (!out.isEmpty())
            return out;
    }
    return {inst};
}

} // namespace

CppEntryPoints::CppEntryPoints(
    const CppClassIndex &index,
    const QHash<QString, QList<CppClassIndex::FunctionRef>> &freeFunctionsByName,
    const CppConstructions &constructions, std::function<QString(int)> ownName)
    : m_index(index), m_freeFunctionsByName(freeFunctionsByName), m_constructions(constructions),
      m_ownName(std::move(ownName))
{
}

void CppEntryPoints::addConstructions(const CppClassIndex::FunctionRef &ref, EntryPoint *entry,
                                      QList<Evidence> *boundsHit) const
{
    const CppFunction &fn = *ref.function;
    QList<const CppFunction *> open{&fn};
    addConstructions(fn, CppLinkContext{-1, &fn, ref.file}, 0, &open, entry, boundsHit);
}

void CppEntryPoints::addConstructions(const CppFunction &fn, const CppLinkContext &ctx, int depth,
                                      QList<const CppFunction *> *open, EntryPoint *entry,
                                      QList<Evidence> *boundsHit) const
{
    for (const CppInstantiation &inst : fn.instantiations) {
        if (inst.className.isEmpty())
            continue;
        // `PassStage<sensor_msgs::msg::LaserScan>`: the class template, built with that type
        const QString written = withoutTemplateArguments(inst.className).remove(u' ');
        const int c = m_index.lookup(written, fn.namespaces, ctx.file);
        if (c < 0 || !m_index.at(c).node)
            continue;
        if (!entry->instantiatedClasses.contains(written))
            entry->instantiatedClasses.append(written);
        // `for (const auto & zone : zones) make_shared<ZoneWatcher>(zone)` over a list of
        // literals: one node per item.
        for (const CppInstantiation &one : perListItem(inst)) {
            NodeConstruction k = m_constructions.construction(c, one, ctx, m_ownName(c));
            k.className = written;
            entry->constructions.append(k);
        }
    }
    // Builder functions are followed from `main` only: what `ros2 run` starts.
    if (depth == 0 && fn.name != QLatin1String("main"))
        return;
    if (depth >= kMaxBuilderDepth) {
        for (const QList<CppFreeCall> *calls : {&fn.builderCalls, &fn.freeCalls})
            for (const CppFreeCall &call : *calls) {
                // said where the function called builds a node itself
                const QStringList called = splitScope(call.function);
                const auto buildsANode = [&](const CppClassIndex::FunctionRef &ref) {
                    return std::any_of(
                        ref.function->instantiations.cbegin(), ref.function->instantiations.cend(),
                        [&](const CppInstantiation &inst) {
                            const int c = m_index.lookup(
                                withoutTemplateArguments(inst.className).remove(u' '),
                                ref.function->namespaces, ref.file);
                            return c >= 0 && m_index.at(c).node;
                        });
                };
                const auto candidates = called.isEmpty()
                                            ? QList<CppClassIndex::FunctionRef>()
                                            : m_freeFunctionsByName.value(called.constLast());
                if (std::any_of(candidates.cbegin(), candidates.cend(), buildsANode)) {
                    boundsHit->append(call.evidence);
                    return;
                }
            }
        return;
    }
    const auto follow = [&](const CppFreeCall &call) {
        const QStringList calledName = splitScope(call.function);
        if (calledName.isEmpty())
            return;
        const QString scope = calledName.mid(0, calledName.size() - 1).join(QStringLiteral("::"));
        const auto n = int(call.arguments.size());
        QList<CppClassIndex::FunctionRef> candidates;
        for (const auto &ref : m_freeFunctionsByName.value(calledName.constLast())) {
            const CppFunction *callee = ref.function;
            const QString ns = callee->namespaces.join(QStringLiteral("::"));
            const bool buildsSomething = !callee->instantiations.isEmpty() ||
                                         !callee->builderCalls.isEmpty() ||
                                         !callee->freeCalls.isEmpty();
            if (open->contains(callee) || !buildsSomething || n < callee->requiredParameters ||
                (!callee->variadic && n > callee->parameterNames.size()) ||
                (!scope.isEmpty() && ns != scope && !ns.endsWith(QStringLiteral("::") + scope)))
                continue;
            candidates.append(ref);
        }
        // A same-named function in the caller's package wins over the rest of the workspace.
        const QString package = ctx.file ? ctx.file->package : QString();
        if (std::any_of(candidates.cbegin(), candidates.cend(),
                        [&](const auto &ref) { return ref.file->package == package; }))
            candidates.removeIf([&](const auto &ref) { return ref.file->package != package; });
        for (const auto &ref : std::as_const(candidates)) {
            const CppFunction *callee = ref.function;
            const CppSubstitution subst{call.arguments, ctx, {}, callee};
            open->append(callee);
            addConstructions(*callee, CppLinkContext{-1, callee, ref.file, &subst}, depth + 1, open,
                             entry, boundsHit);
            open->removeLast();
        }
    };
    for (const CppFreeCall &call : fn.builderCalls)
        follow(call);
    for (const CppFreeCall &call : fn.freeCalls)
        follow(call);
}

} // namespace rosarch
