#include "cppparameterlinker.h"

#include "cppsyntax.h"
#include "declaringcall.h"

using namespace rosarch::cppsyntax;

#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace rosarch {

CppParameterLinker::CppParameterLinker(const CppClassIndex &index, const CppNameResolver &names,
                                       const CppHelperPorts &helpers)
    : m_index(index), m_names(names), m_helpers(helpers)
{
    for (const auto &ref : m_index.freeFunctions())
        if (ref.function->name != QLatin1String("main"))
            m_freeFunctions[ref.function->name].append(ref);
}

QList<ParameterDeclaration>
CppParameterLinker::declarations(int cls, const std::map<int, CppSubstitution> *substitutions) const
{
    QList<ParameterDeclaration> out;
    QStringList undeclared;
    QList<int> visited;
    collect(cls, cls, substitutions, 0, &visited, &out, &undeclared);
    // one entry per name: the first declaration is the one that takes effect
    QList<ParameterDeclaration> unique;
    QSet<QString> seen;
    for (const ParameterDeclaration &p : std::as_const(out)) {
        if (undeclared.contains(p.name) || seen.contains(p.name))
            continue;
        seen.insert(p.name);
        unique.append(p);
    }
    std::stable_sort(unique.begin(), unique.end(),
                     [](const ParameterDeclaration &a, const ParameterDeclaration &b) {
                         return evidenceLess(a.evidence, b.evidence);
                     });
    return unique;
}

// The declarations of `cls`'s lineage, and of the project helper classes its code constructs
// (a ParameterHandler handed the node declares the node's parameters).
void CppParameterLinker::collect(int cls, int node,
                                 const std::map<int, CppSubstitution> *substitutions, int depth,
                                 QList<int> *visited, QList<ParameterDeclaration> *out,
                                 QStringList *undeclared) const
{
    if (visited->contains(cls))
        return;
    visited->append(cls);
    for (int c : m_index.lineage(cls)) {
        const CppClassIndex::ClassInfo &info = m_index.at(c);
        const CppSubstitution *subst = nullptr;
        if (substitutions) {
            const auto it = substitutions->find(c);
            subst = it == substitutions->end() ? nullptr : &it->second;
        }
        for (const auto &ref : info.functions) {
            const CppLinkContext ctx{c, ref.function, ref.file, subst, substitutions ? node : -1};
            addDeclarations(*ref.function, ctx, c != node, out, undeclared);
            addFreeCalls(*ref.function, ctx, node, depth, out, undeclared);
            const CppLinkContext here{c, ref.function, ref.file, nullptr};
            for (const CppInstantiation &inst : ref.function->instantiations) {
                if (inst.className.isEmpty())
                    continue;
                const int t = m_index.lookup(withoutTemplateArguments(inst.className).remove(u' '),
                                             m_names.scopeOf(here), ref.file);
                if (t < 0 || m_index.at(t).node)
                    continue;
                // the helpers' bound, said the way their ports say it (helper-depth)
                if (depth + 1 > CppHelperPorts::kMaxHelperDepth)
                    m_helpers.boundHit(inst.evidence);
                else
                    collect(t, node, nullptr, depth + 1, visited, out, undeclared);
            }
        }
    }
}

QList<ParameterDeclaration> CppParameterLinker::helperDeclarations() const
{
    QList<ParameterDeclaration> out;
    QSet<QString> seen;
    auto add = [&](const CppClassIndex::FunctionRef &ref, int cls) {
        const CppLinkContext ctx{cls, ref.function, ref.file, nullptr};
        for (const CppParameterDeclaration &d : ref.function->parameterDeclarations) {
            if (d.via.isEmpty() || d.via == QLatin1String("undeclare") ||
                (d.parameter.isEmpty() && d.name.kind == CppValue::Kind::FunctionParameter))
                continue;
            ParameterDeclaration p;
            p.name = nameOf(d, ctx);
            // a name that is all run-time parts (`{param}`) says nothing about any key
            if (seen.contains(p.name) || parameterNameIsOpen(p.name))
                continue;
            seen.insert(p.name);
            p.type = d.type;
            p.via = d.via;
            p.evidence = d.evidence;
            out.append(p);
        }
    };
    for (const auto &ref : m_index.freeFunctions())
        add(ref, -1);
    for (int c = 0; c < m_index.size(); ++c)
        if (!m_index.at(c).node)
            for (const auto &ref : m_index.at(c).functions)
                add(ref, c);
    std::sort(out.begin(), out.end(),
              [](const ParameterDeclaration &a, const ParameterDeclaration &b) {
                  return a.name < b.name;
              });
    return out;
}

void CppParameterLinker::addDeclarations(const CppFunction &fn, const CppLinkContext &ctx,
                                         bool inherited, QList<ParameterDeclaration> *out,
                                         QStringList *undeclared) const
{
    for (const CppParameterDeclaration &d : fn.parameterDeclarations) {
        if (d.via.isEmpty())
            continue;
        if (d.parameter.isEmpty() && d.name.kind == CppValue::Kind::FunctionParameter) {
            // A declaring helper of the class (`declare_or_get_parameter(name, ...)`) declares
            // what its callers name, and those calls are read where they are; any other
            // function taking the name may declare anything.
            const QString name = fn.name.toLower();
            if (name.contains(QLatin1String("declare")) &&
                name.contains(QLatin1String("parameter")))
                continue;
        }
        const QString name = nameOf(d, ctx);
        if (d.via == QLatin1String("undeclare")) {
            undeclared->append(name);
            continue;
        }
        ParameterDeclaration p;
        p.name = name;
        p.nameExpression = d.parameter.isEmpty() ? d.name.text : QString();
        p.type = d.type;
        if (p.type.isEmpty() && d.defaultValue.kind == CppValue::Kind::Member && ctx.cls >= 0)
            p.type = parameterTypeOfWritten(
                m_index.at(ctx.cls).cls->memberTypes.value(d.defaultValue.variable));
        p.hasDefault = d.hasDefault;
        p.defaultValue = p.hasDefault ? defaultOf(d, ctx) : QString();
        p.readOnly = d.readOnly;
        p.dynamicTyping = d.dynamicTyping;
        p.description = d.description;
        p.range = d.range;
        p.guard = d.guard;
        p.via = d.via;
        p.inherited = inherited;
        p.evidence = d.evidence;
        out->append(p);
    }
}

// Free functions the code calls with its node (`getTargetObjectType(*this, "prefix.")`)
// declare on it, with the call's arguments for their parameters.
void CppParameterLinker::addFreeCalls(const CppFunction &fn, const CppLinkContext &ctx, int node,
                                      int depth, QList<ParameterDeclaration> *out,
                                      QStringList *undeclared) const
{
    for (const CppFreeCall &call : fn.freeCalls) {
        if (std::none_of(call.arguments.begin(), call.arguments.end(),
                         [&](const CppValue &a) { return m_names.isNodeHandle(a, ctx); }))
            continue;
        if (depth + 1 > CppHelperPorts::kMaxHelperDepth) {
            m_helpers.boundHit(call.evidence);
            continue;
        }
        const QString name = lastSegment(call.function);
        for (const auto &ref : m_freeFunctions.value(name)) {
            const CppFunction *callee = ref.function;
            const int n = int(call.arguments.size());
            if (callee == ctx.fn || n < callee->requiredParameters ||
                (!callee->variadic && n > callee->parameterNames.size()))
                continue;
            const CppSubstitution subst{call.arguments, ctx, {}, callee};
            const CppLinkContext inner{-1, callee, ref.file, &subst};
            addDeclarations(*callee, inner, true, out, undeclared);
            addFreeCalls(*callee, inner, node, depth + 1, out, undeclared);
        }
    }
}

bool CppParameterLinker::acceptsUndeclared(int cls) const
{
    QSet<const CppFileFacts *> files;
    for (int c : m_index.lineage(cls)) {
        files.insert(m_index.at(c).file);
        for (const auto &ref : m_index.at(c).functions) {
            if (ref.function->acceptsUndeclared)
                return true;
            files.insert(ref.file);
        }
    }
    for (const auto &ref : m_index.freeFunctions())
        if (ref.function->acceptsUndeclared && files.contains(ref.file))
            return true;
    return false;
}

QString CppParameterLinker::nameOf(const CppParameterDeclaration &d,
                                   const CppLinkContext &ctx) const
{
    if (!d.parameter.isEmpty()) {
        // a project's own declaring helper may put a prefix before the name it is given
        const bool known = isStandardDeclaringCall(d.via) ||
                           d.via == QLatin1String("get_parameter_or") ||
                           d.via == QLatin1String("undeclare");
        return known ? d.parameter : QStringLiteral("{%1}").arg(d.via) + d.parameter;
    }
    return textOf(d.name, ctx);
}

// A default as text: what it resolves to, else as written.
QString CppParameterLinker::defaultOf(const CppParameterDeclaration &d,
                                      const CppLinkContext &ctx) const
{
    const CppValue &value = d.defaultValue;
    if (value.kind == CppValue::Kind::Literal || value.kind == CppValue::Kind::Local)
        return value.literal;
    if (value.kind == CppValue::Kind::Member || value.kind == CppValue::Kind::Constant) {
        const CppResolvedName r = m_names.resolve(value, ctx);
        if (r.origin != NameOrigin::Expression)
            return r.name;
    }
    // a list written as a braced initializer (`std::vector<double>{0.5, 0.0}`) reads as the
    // list ROS 2 takes: [0.5, 0.0]
    static const QRegularExpression list(
        QStringLiteral("^(?:[\\w:]*vector\\s*<.*>\\s*)?\\{(.*)\\}$"));
    const QRegularExpressionMatch m = list.match(d.defaultText);
    if (m.hasMatch() && d.type.endsWith(QLatin1String("_array"))) {
        QStringList items;
        for (QString item : m.captured(1).split(u',', Qt::SkipEmptyParts)) {
            item = item.trimmed();
            if (item.size() >= 2 && item.startsWith(u'"') && item.endsWith(u'"'))
                item = item.mid(1, item.size() - 2);
            items << item;
        }
        return QLatin1Char('[') + items.join(QStringLiteral(", ")) + QLatin1Char(']');
    }
    return d.defaultText;
}

// A value as text: what it resolves to, else each part of a joined value that resolves, with
// `{text}` for a part that does not.
QString CppParameterLinker::textOf(const CppValue &value, const CppLinkContext &ctx) const
{
    if (value.kind == CppValue::Kind::Literal || value.kind == CppValue::Kind::Local)
        return value.literal;
    const CppResolvedName r = m_names.resolve(value, ctx);
    if (r.origin != NameOrigin::Expression)
        return r.name;
    // a constant defined outside the workspace (`bond::msg::Constants::..._PARAM`) is one name
    // the analysis does not know, not any name
    if (value.kind == CppValue::Kind::Constant)
        return value.text;
    if (value.kind != CppValue::Kind::Concatenation)
        return QStringLiteral("{%1}").arg(value.text);
    QString out;
    for (const CppValue &part : value.parts)
        out += textOf(part, ctx);
    return out;
}

} // namespace rosarch
