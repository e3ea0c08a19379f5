#include "nodes/cpp/cppparameterlinker.h"

#include "core/declaringcall.h"
#include "syntax/cppsyntax.h"

using namespace rosarch::cppsyntax;

#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace rosarch {

CppParameterLinker::CppParameterLinker(const QList<CppFileFacts> &files, const CppClassIndex &index,
                                       const CppNameResolver &names, const CppHelperPorts &helpers)
    : m_index(index), m_names(names), m_helpers(helpers)
{
    for (const auto &ref : m_index.freeFunctions())
        if (ref.function->name != QLatin1String("main"))
            m_freeFunctions[ref.function->name].append(ref);
    for (const CppFileFacts &file : files)
        for (const CppPluginExport &e : file.pluginExports) {
            m_pluginClasses.insert(lastSegment(e.className));
            m_pluginClasses.insert(lastSegment(e.baseClass));
        }
}

QList<ParameterDeclaration>
CppParameterLinker::declarations(int cls, const std::map<int, CppSubstitution> *substitutions) const
{
    QList<ParameterDeclaration> out;
    QStringList undeclared;
    QList<int> visited;
    collect(cls, cls, substitutions, substitutions ? cls : -1, 0, &visited, &out, &undeclared);
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
// (a ParameterHandler handed the node declares the node's parameters) or holds as members (an
// optimizer a controller plugin configures with its name). `self` is the object the code runs
// in (-1: none known); a plugin's, and its helpers', hold the name it is loaded under.
void CppParameterLinker::collect(int cls, int node,
                                 const std::map<int, CppSubstitution> *substitutions, int self,
                                 int depth, QList<int> *visited, QList<ParameterDeclaration> *out,
                                 QStringList *undeclared) const
{
    if (visited->contains(cls))
        return;
    visited->append(cls);
    QList<int> helpers; // member helpers, followed after the code that configures them
    for (int c : m_index.lineage(cls)) {
        const CppClassIndex::ClassInfo &info = m_index.at(c);
        const CppSubstitution *subst = nullptr;
        if (substitutions) {
            const auto it = substitutions->find(c);
            subst = it == substitutions->end() ? nullptr : &it->second;
        }
        for (const auto &ref : info.functions) {
            const CppLinkContext ctx{c, ref.function, ref.file, subst, self};
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
                if (depth + 1 > CppHelperPorts::kMaxHelperDepth) {
                    m_helpers.boundHit(inst.evidence);
                    continue;
                }
                if (self < 0) {
                    collect(t, node, nullptr, -1, depth + 1, visited, out, undeclared);
                    continue;
                }
                // a plugin's helper is handed the plugin's name among its arguments
                const std::map<int, CppSubstitution> constructed{
                    {t, CppSubstitution{inst.arguments, ctx, {}, nullptr}}};
                collect(t, node, &constructed, t, depth + 1, visited, out, undeclared);
            }
        }
        if (info.cls)
            for (auto it = info.cls->memberTypes.cbegin(); it != info.cls->memberTypes.cend();
                 ++it) {
                const int t = memberHelper(it.value(), c);
                if (t >= 0 && !helpers.contains(t))
                    helpers.append(t);
            }
    }
    for (int t : std::as_const(helpers)) {
        if (depth + 1 > CppHelperPorts::kMaxHelperDepth)
            continue;
        collect(t, node, nullptr, self >= 0 ? t : -1, depth + 1, visited, out, undeclared);
    }
}

// A member's class when it is a workspace class that is no node and declares parameters on a
// node it is handed (`Optimizer optimizer_;`, `std::unique_ptr<CriticManager> manager_;`).
int CppParameterLinker::memberHelper(const QString &type, int cls) const
{
    static const QRegularExpression pointer(
        QStringLiteral("^(?:std::)?(?:unique_ptr|shared_ptr)<(.+)>$"));
    QString written = type.simplified().remove(u' ');
    written.remove(QStringLiteral("const"));
    written.remove(u'*');
    written.remove(u'&');
    if (const QRegularExpressionMatch m = pointer.match(written); m.hasMatch())
        written = m.captured(1);
    for (const char *alias : {"::SharedPtr", "::UniquePtr", "::Ptr"})
        if (written.endsWith(QLatin1String(alias)))
            written.chop(int(qstrlen(alias)));
    if (written.isEmpty() || written.contains(u'<') || written.startsWith(QLatin1String("std::")))
        return -1;
    const CppClassIndex::ClassInfo &info = m_index.at(cls);
    const CppLinkContext here{cls, nullptr, info.file, nullptr};
    const int t = m_index.lookup(written, m_names.scopeOf(here), info.file);
    // a plugin, or its interface, is loaded by a name of its own and declares under it
    if (t < 0 || t == cls || m_index.at(t).node ||
        m_pluginClasses.contains(m_index.at(t).cls ? m_index.at(t).cls->name : QString()))
        return -1;
    for (const auto &ref : m_index.at(t).functions)
        if (!ref.function->parameterDeclarations.isEmpty())
            return t;
    return -1;
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
        const auto ownParameter = [](const CppValue &v) {
            return v.kind == CppValue::Kind::FunctionParameter;
        };
        if (d.parameter.isEmpty() &&
            (ownParameter(d.name) ||
             (d.name.kind == CppValue::Kind::Concatenation &&
              std::any_of(d.name.parts.begin(), d.name.parts.end(), ownParameter)))) {
            // A declaring helper of the class (`declare_or_get_parameter(name, ...)`) declares
            // what its callers name, and those calls are read where they are; any other
            // function taking the name may declare anything.
            const QString name = fn.name.toLower();
            if (name.contains(QLatin1String("declare")) &&
                name.contains(QLatin1String("parameter")))
                continue;
        }
        const QString name = nameOf(d, ctx);
        // helper code that declares the name its callers give it (a parameters handler's
        // `getParam(setting, name, default)`): the callers' declarations are read where they are
        if (inherited && d.parameter.isEmpty() &&
            d.name.kind == CppValue::Kind::FunctionParameter && parameterNameIsOpen(name) &&
            ctx.cls >= 0 && !m_index.at(ctx.cls).node)
            continue;
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
        if (known)
            return d.parameter;
        const QString named = helperName(d, ctx);
        return named.isEmpty() ? QStringLiteral("{%1}").arg(d.via) + d.parameter : named;
    }
    return textOf(d.name, ctx);
}

// The name a declaring method of the class (`declareParameter("enabled", value)` of a
// costmap layer) gives what it is handed: its own declaring call's name with the call's
// arguments for its parameters (`name_ + "." + param_name`); "" when that stays undecided.
QString CppParameterLinker::helperName(const CppParameterDeclaration &d,
                                       const CppLinkContext &ctx) const
{
    const int from = ctx.self >= 0 ? ctx.self : ctx.cls;
    if (from < 0)
        return {};
    CppValue name;
    name.kind = CppValue::Kind::Literal;
    name.literal = name.text = d.parameter;
    for (int c : m_index.lineage(from))
        for (const auto &ref : m_index.at(c).functions) {
            const CppFunction *fn = ref.function;
            if (fn->name != d.via || fn->parameterNames.isEmpty())
                continue;
            for (const CppParameterDeclaration &inner : fn->parameterDeclarations) {
                if (!isStandardDeclaringCall(inner.via) || !inner.parameter.isEmpty())
                    continue;
                const CppSubstitution subst{{name, d.defaultValue}, ctx, {}, fn};
                const CppLinkContext at{c, fn, ref.file, &subst, ctx.self};
                const QString out = textOf(inner.name, at);
                if (!out.isEmpty() && !parameterNameIsPattern(out))
                    return out;
            }
        }
    return {};
}

// A default as text: what it resolves to, else as written.
QString CppParameterLinker::defaultOf(const CppParameterDeclaration &d,
                                      const CppLinkContext &ctx) const
{
    // a number as C++ writes it (`0.5f`, `10u`) reads as the number ROS 2 takes
    static const QRegularExpression suffixed(
        QStringLiteral("^([-+]?(?:[0-9]+\\.?[0-9]*|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?)[fFlLuU]+$"));
    const CppValue &value = d.defaultValue;
    if (value.kind == CppValue::Kind::Literal || value.kind == CppValue::Kind::Local) {
        const QRegularExpressionMatch n = suffixed.match(value.literal);
        return n.hasMatch() ? n.captured(1) : value.literal;
    }
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
    if (const QRegularExpressionMatch n = suffixed.match(d.defaultText); n.hasMatch())
        return n.captured(1);
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
