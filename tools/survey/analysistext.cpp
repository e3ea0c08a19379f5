#include "analysistext.h"

namespace rosarch::AnalysisText {

namespace {

using K = LaunchAction::Kind;

void describe(const LaunchAction &a, int depth, QStringList &out)
{
    QStringList f{actionKind(a.kind)};
    auto add = [&](const char *key, const Substitution &s) {
        if (!s.isEmpty())
            f << QStringLiteral("%1=%2").arg(QLatin1String(key), substitution(s));
    };
    add("pkg", a.package);
    add("exe", a.executable);
    add("plugin", a.plugin);
    add("name", a.name);
    add("ns", a.nameSpace);
    if (a.lifecycle)
        f << QStringLiteral("lifecycle");
    if (a.kind == K::Group)
        f << (a.scoped ? QStringLiteral("scoped") : QStringLiteral("unscoped"));
    add("target", a.target);
    add("path", a.path);
    for (const auto &arg : a.arguments)
        f << QStringLiteral("arg:%1=%2").arg(substitution(arg.first), substitution(arg.second));
    for (const LaunchRemap &r : a.remaps)
        f << QStringLiteral("remap:%1->%2").arg(substitution(r.from), substitution(r.to));
    for (const LaunchParameter &p : a.parameters)
        f << (p.isFile
                  ? QStringLiteral("paramfile:%1").arg(substitution(p.value))
                  : QStringLiteral("param:%1=%2").arg(substitution(p.name), substitution(p.value)));
    if (a.hasValue)
        f << QStringLiteral("value=%1").arg(substitution(a.value));
    if (!a.description.isEmpty())
        f << QStringLiteral("desc=%1").arg(a.description);
    if (!a.expression.isEmpty())
        f << QStringLiteral("expr=%1").arg(a.expression);
    if (a.condition.isSet())
        f << QStringLiteral("%1(%2)").arg(a.condition.unless ? QStringLiteral("unless")
                                                             : QStringLiteral("if"),
                                          substitution(a.condition.expression));
    f << QStringLiteral("@%1").arg(a.evidence.line);
    // Every action, remap and parameter carries evidence: the call expression.
    bool evidenceOk = a.evidence.isValid();
    for (const LaunchRemap &r : a.remaps)
        evidenceOk = evidenceOk && r.evidence == a.evidence;
    for (const LaunchParameter &p : a.parameters)
        evidenceOk = evidenceOk && p.evidence == a.evidence;
    if (!evidenceOk)
        f << QStringLiteral("BAD-EVIDENCE");
    out << QString(depth * 2, QLatin1Char(' ')) + f.join(QLatin1Char(' '));
    for (const LaunchAction &c : a.children)
        describe(c, depth + 1, out);
}

} // namespace

QString port(const Port &p)
{
    return QStringLiteral(
               "%1 %2 %3 cb=%4 origin=%5 expr=%6 param=%7 guard=%8 gp=%9 via=%10%11 @%12:%13")
        .arg(portKindName(p.kind), p.name, p.type, p.callback, nameOriginName(p.nameOrigin),
             p.nameExpression, p.parameter, p.guard, p.guardParameter)
        .arg(p.via, p.inherited ? QStringLiteral(" inherited") : QString(), p.evidence.file)
        .arg(p.evidence.line);
}

QString analysis(const LanguageAnalysis &a)
{
    QString s;
    for (const AtomicNode &n : a.nodes) {
        s += QStringLiteral("%1 [%2] %3 name='%4' bases=(%5)%6%7 @%8:%9-%10 hdr=%11 src=%12\n")
                 .arg(n.className, n.packageName, n.qualifiedName, n.nodeName,
                      n.baseClasses.join(QLatin1Char(',')),
                      n.lifecycle ? QStringLiteral(" lifecycle") : QString(),
                      n.procedural ? QStringLiteral(" procedural") : QString(), n.evidence.file)
                 .arg(n.evidence.line)
                 .arg(n.evidence.endLine)
                 .arg(n.headerFiles.join(QLatin1Char(',')), n.sourceFiles.join(QLatin1Char(',')));
        for (const Port &p : n.ports)
            s += QStringLiteral("    ") + port(p) + QLatin1Char('\n');
    }
    for (const EntryPoint &e : a.entryPoints)
        s += QStringLiteral("entry %1:%2 -> %3\n")
                 .arg(e.file, e.function, e.instantiatedClasses.join(QLatin1Char(' ')));
    for (const ComponentRegistration &r : a.registrations)
        s += QStringLiteral("register %1 @%2:%3\n").arg(r.pluginClass, r.file).arg(r.evidence.line);
    for (const Diagnostic &d : a.diagnostics)
        s += QStringLiteral("diag %1 %2\n").arg(d.code, d.message);
    return s;
}

QString substitution(const Substitution &s)
{
    auto joined = [&](const QString &sep) {
        QStringList out;
        for (const Substitution &p : s.parts)
            out << substitution(p);
        return out.join(sep);
    };
    using SK = Substitution::Kind;
    switch (s.kind) {
    case SK::Text:
        return s.text;
    case SK::LaunchConfiguration:
        return s.parts.isEmpty()
                   ? QStringLiteral("$(var %1)").arg(s.text)
                   : QStringLiteral("$(var %1|%2)").arg(s.text, joined(QStringLiteral(",")));
    case SK::EnvironmentVariable:
        return s.parts.isEmpty()
                   ? QStringLiteral("$(env %1)").arg(s.text)
                   : QStringLiteral("$(env %1|%2)").arg(s.text, joined(QStringLiteral(",")));
    case SK::FindPackageShare:
        return QStringLiteral("$(find-pkg-share %1)").arg(joined(QString()));
    case SK::FindPackagePrefix:
        return QStringLiteral("$(find-pkg-prefix %1)").arg(joined(QString()));
    case SK::PathJoin:
        return QStringLiteral("join[%1]").arg(joined(QStringLiteral(", ")));
    case SK::Concat:
        return QStringLiteral("cat[%1]").arg(joined(QStringLiteral(", ")));
    case SK::Eval:
        return QStringLiteral("$(eval %1)").arg(joined(QStringLiteral(" ~ ")));
    case SK::ThisLaunchFileDir:
        return QStringLiteral("$(dirname)");
    case SK::ThisLaunchFile:
        return QStringLiteral("$(filename)");
    case SK::RewrittenYaml:
        return QStringLiteral("RewrittenYaml(%1)").arg(joined(QStringLiteral(", ")));
    case SK::Unknown:
        return QStringLiteral("?{%1}").arg(s.text);
    case SK::Function:
        return QStringLiteral("$(%1 %2)").arg(s.text, joined(QStringLiteral(" ")));
    }
    return {};
}

QString actionKind(LaunchAction::Kind k)
{
    switch (k) {
    case K::Node:
        return QStringLiteral("Node");
    case K::ComposableContainer:
        return QStringLiteral("Container");
    case K::ComposableNode:
        return QStringLiteral("Composable");
    case K::LoadComposableNodes:
        return QStringLiteral("Load");
    case K::Include:
        return QStringLiteral("Include");
    case K::Group:
        return QStringLiteral("Group");
    case K::PushNamespace:
        return QStringLiteral("PushNs");
    case K::SetRemap:
        return QStringLiteral("SetRemap");
    case K::DeclareArgument:
        return QStringLiteral("Arg");
    case K::SetLaunchConfiguration:
        return QStringLiteral("Let");
    case K::SetParameter:
        return QStringLiteral("SetParam");
    case K::Unresolved:
        return QStringLiteral("Unresolved");
    }
    return {};
}

QStringList actions(const QList<LaunchAction> &list)
{
    QStringList out;
    for (const LaunchAction &a : list)
        describe(a, 0, out);
    return out;
}

void tally(const QList<LaunchAction> &list, QMap<QString, int> *kinds,
           QMap<QString, int> *unresolved)
{
    for (const LaunchAction &a : list) {
        ++(*kinds)[actionKind(a.kind)];
        if (a.kind == K::Unresolved)
            ++(*unresolved)[a.expression.section(QLatin1Char('('), 0, 0)
                                .section(QLatin1Char('.'), -1)];
        if (a.kind == K::Group && a.condition.expression.kind == Substitution::Kind::Unknown)
            ++(*unresolved)[QStringLiteral("<undecided if/for>")];
        tally(a.children, kinds, unresolved);
    }
}

} // namespace rosarch::AnalysisText
