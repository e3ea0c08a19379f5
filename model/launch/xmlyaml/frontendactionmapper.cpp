#include "launch/xmlyaml/frontendactionmapper.h"
#include "launch/xmlyaml/frontendsubstitution.h"

#include <QSet>

namespace rosarch {

namespace {

using Kind = LaunchAction::Kind;

// The readers already cap nesting; this is a second fence for entities built elsewhere.
constexpr int kMaxDepth = 256;

// Entities that change nothing the architecture shows.
const QSet<QString> &ignoredTypes()
{
    static const QSet<QString> types{
        QStringLiteral("set_env"),        QStringLiteral("unset_env"), QStringLiteral("append_env"),
        QStringLiteral("prepend_env"),    QStringLiteral("reset_env"), QStringLiteral("log"),
        QStringLiteral("set_ros_log_dir")};
    return types;
}

Substitution dotted(const Substitution &prefix, const Substitution &name)
{
    if (prefix.isEmpty())
        return name;
    QList<Substitution> parts;
    auto append = [&](const Substitution &s) {
        const QList<Substitution> pieces =
            s.kind == Substitution::Kind::Concat ? s.parts : QList<Substitution>{s};
        for (const Substitution &p : pieces) {
            if (p.isLiteral() && !parts.isEmpty() && parts.last().isLiteral())
                parts.last().text += p.text;
            else
                parts << p;
        }
    };
    append(prefix);
    append(Substitution::literal(QStringLiteral(".")));
    append(name);
    return Substitution::concat(parts);
}

bool isFalse(const QString &text)
{
    const QString t = text.trimmed().toLower();
    return t == u"false" || t == u"0" || t == u"no" || t == u"off";
}

// Splits a command line at white space outside quotes and `$(...)`; outer quotes are dropped.
QStringList splitCommandLine(const QString &s)
{
    QStringList out;
    QString token;
    bool inToken = false;
    int depth = 0;
    QChar quote;
    for (qsizetype i = 0; i < s.size(); ++i) {
        const QChar c = s[i];
        if (!quote.isNull()) {
            if (c == quote)
                quote = QChar();
            else
                token += c;
            continue;
        }
        if (depth == 0 && c.isSpace()) {
            if (inToken)
                out << token;
            token.clear();
            inToken = false;
            continue;
        }
        inToken = true;
        if (depth == 0 && (c == u'\'' || c == u'"')) {
            quote = c;
            continue;
        }
        if (c == u'$' && i + 1 < s.size() && s[i + 1] == u'(') {
            ++depth;
            token += c;
            token += s[++i];
            continue;
        }
        if (c == u')' && depth > 0)
            --depth;
        token += c;
    }
    if (inToken)
        out << token;
    return out;
}

} // namespace

QList<LaunchAction> FrontendActionMapper::map(const QList<FrontendEntity> &entities)
{
    QList<LaunchAction> out;
    for (const FrontendEntity &e : entities)
        mapInto(e, &out);
    return out;
}

void FrontendActionMapper::report(const QString &code, const QString &message,
                                  const Evidence &evidence, Diagnostic::Severity severity)
{
    if (!m_diagnostics)
        return;
    Diagnostic d;
    d.severity = severity;
    d.code = code;
    d.message = message;
    d.evidence = evidence;
    m_diagnostics->append(d);
}

Substitution FrontendActionMapper::value(const FrontendEntity &e, const FrontendAttribute &a)
{
    QString error;
    Substitution s = FrontendSubstitution::parse(a.value, &error);
    if (!error.isEmpty()) {
        report(QStringLiteral("malformed-substitution"),
               QStringLiteral("Cannot read the substitution in attribute '%1' of <%2>: %3.")
                   .arg(a.name, e.type, error),
               a.evidence);
    }
    return s;
}

Substitution FrontendActionMapper::value(const FrontendEntity &e, const QString &name,
                                         bool required)
{
    if (const FrontendAttribute *a = e.attribute(name))
        return value(e, *a);
    if (required) {
        report(QStringLiteral("missing-attribute"),
               QStringLiteral("<%1> has no '%2' attribute.").arg(e.type, name), e.evidence);
    }
    return {};
}

LaunchCondition FrontendActionMapper::condition(const FrontendEntity &e)
{
    LaunchCondition c;
    const FrontendAttribute *ifAttr = e.attribute(QStringLiteral("if"));
    const FrontendAttribute *unlessAttr = e.attribute(QStringLiteral("unless"));
    if (ifAttr && unlessAttr) {
        report(QStringLiteral("conflicting-conditions"),
               QStringLiteral("<%1> has both 'if' and 'unless'; only 'if' is used.").arg(e.type),
               e.evidence);
    }
    const FrontendAttribute *a = ifAttr ? ifAttr : unlessAttr;
    if (!a)
        return c;
    c.expression = value(e, *a);
    c.unless = a == unlessAttr;
    c.text = a->value;
    return c;
}

QList<LaunchRemap> FrontendActionMapper::remaps(const FrontendEntity &e)
{
    QList<LaunchRemap> out;
    for (const FrontendEntity *r : e.childrenOfType(QStringLiteral("remap"))) {
        LaunchRemap remap;
        remap.from = value(*r, QStringLiteral("from"), true);
        remap.to = value(*r, QStringLiteral("to"), true);
        remap.evidence = r->evidence;
        out << remap;
    }
    return out;
}

// <param name value/>, <param from/>, and nested <param name><param name value/></param>
// flattened to "outer.inner" as launch_ros does.
void FrontendActionMapper::parameters(const FrontendEntity &e, const Substitution &prefix,
                                      QList<LaunchParameter> *out)
{
    for (const FrontendEntity *p : e.childrenOfType(QStringLiteral("param"))) {
        LaunchParameter param;
        param.evidence = p->evidence;
        if (const FrontendAttribute *from = p->attribute(QStringLiteral("from"));
            from && prefix.isEmpty()) {
            param.isFile = true;
            param.value = value(*p, *from);
            *out << param;
            continue;
        }
        const FrontendAttribute *name = p->attribute(QStringLiteral("name"));
        if (!name) {
            report(QStringLiteral("missing-attribute"),
                   QStringLiteral("<param> has neither 'name' nor 'from'."), p->evidence);
            continue;
        }
        param.name = dotted(prefix, value(*p, *name));
        if (const FrontendAttribute *v = p->attribute(QStringLiteral("value"))) {
            param.value = value(*p, *v);
            *out << param;
        } else if (!p->childrenOfType(QStringLiteral("param")).isEmpty()) {
            parameters(*p, param.name, out);
        } else {
            report(QStringLiteral("missing-attribute"),
                   QStringLiteral("<param> '%1' has neither a value nor nested parameters.")
                       .arg(name->value),
                   p->evidence);
        }
    }
}

// `--ros-args -r from:=to -p name:=value --params-file f` in `args` (after --ros-args) or
// `ros_args` (all of it): remaps and parameters are part of the node's architecture.
void FrontendActionMapper::commandLine(const FrontendEntity &e, const FrontendAttribute &a,
                                       bool rosArgsOnly, LaunchAction *node)
{
    const QStringList tokens = splitCommandLine(a.value);
    bool inRosArgs = !rosArgsOnly;
    auto parse = [&](const QString &text) {
        FrontendAttribute piece = a;
        piece.value = text;
        return value(e, piece);
    };
    for (qsizetype i = 0; i < tokens.size(); ++i) {
        const QString &t = tokens[i];
        if (t == u"--ros-args") {
            inRosArgs = true;
            continue;
        }
        if (t == u"--") {
            inRosArgs = !rosArgsOnly;
            continue;
        }
        if (!inRosArgs || i + 1 >= tokens.size())
            continue;
        const QString &arg = tokens[i + 1];
        const auto assign = arg.indexOf(QStringLiteral(":="));
        if ((t == u"-r" || t == u"--remap") && assign > 0) {
            ++i;
            const QString from = arg.left(assign);
            const Substitution to = parse(arg.mid(assign + 2));
            if (from == u"__ns" || from == u"__node" || from == u"__name") {
                Substitution &target = from == u"__ns" ? node->nameSpace : node->name;
                if (target.isEmpty())
                    target = to;
                continue;
            }
            node->remaps << LaunchRemap{parse(from), to, a.evidence};
        } else if ((t == u"-p" || t == u"--param") && assign > 0) {
            ++i;
            node->parameters << LaunchParameter{parse(arg.left(assign)), parse(arg.mid(assign + 2)),
                                                false, a.evidence};
        } else if (t == u"--params-file") {
            ++i;
            node->parameters << LaunchParameter{{}, parse(arg), true, a.evidence};
        }
    }
}

LaunchAction FrontendActionMapper::start(const FrontendEntity &e, LaunchAction::Kind kind)
{
    LaunchAction a;
    a.kind = kind;
    a.evidence = e.evidence;
    a.condition = condition(e);
    return a;
}

LaunchAction FrontendActionMapper::node(const FrontendEntity &e, LaunchAction::Kind kind)
{
    LaunchAction a = start(e, kind);
    a.package = value(e, QStringLiteral("pkg"));
    a.executable = value(e, QStringLiteral("exec"), true);
    a.name = value(e, QStringLiteral("name"));
    if (a.name.isEmpty())
        a.name = value(e, QStringLiteral("node-name"));
    a.nameSpace = value(e, QStringLiteral("namespace"));
    if (a.nameSpace.isEmpty())
        a.nameSpace = value(e, QStringLiteral("ns")); // ROS 1 habit, harmless to accept
    a.lifecycle = e.type == u"lifecycle_node";
    a.remaps = remaps(e);
    parameters(e, {}, &a.parameters);
    if (const FrontendAttribute *args = e.attribute(QStringLiteral("args"))) {
        commandLine(e, *args, true, &a);
        for (const QString &word : splitCommandLine(args->value)) {
            FrontendAttribute piece = *args;
            piece.value = word;
            a.commandLine << value(e, piece);
        }
    }
    if (const FrontendAttribute *args = e.attribute(QStringLiteral("ros_args")))
        commandLine(e, *args, false, &a);
    if (kind == Kind::ComposableContainer) {
        for (const FrontendEntity *c : e.childrenOfType(QStringLiteral("composable_node")))
            a.children << composableNode(*c);
    }
    return a;
}

LaunchAction FrontendActionMapper::composableNode(const FrontendEntity &e)
{
    LaunchAction a = start(e, Kind::ComposableNode);
    a.package = value(e, QStringLiteral("pkg"), true);
    a.plugin = value(e, QStringLiteral("plugin"), true);
    a.name = value(e, QStringLiteral("name"));
    a.nameSpace = value(e, QStringLiteral("namespace"));
    a.remaps = remaps(e);
    parameters(e, {}, &a.parameters);
    // extra_arg (use_intra_process_comms, ...) configures loading, not the architecture.
    return a;
}

LaunchAction FrontendActionMapper::group(const FrontendEntity &e)
{
    LaunchAction a = start(e, Kind::Group);
    if (e.type == u"timer" || e.type == u"ros_timer") {
        a.scoped = false; // a timer runs its actions later, in the enclosing scope
    } else if (const FrontendAttribute *scoped = e.attribute(QStringLiteral("scoped"))) {
        a.scoped = !isFalse(scoped->value);
    }
    if (const FrontendAttribute *ns = e.attribute(QStringLiteral("ns"))) {
        LaunchAction push;
        push.kind = Kind::PushNamespace;
        push.evidence = ns->evidence;
        push.nameSpace = value(e, *ns);
        a.children << push;
    }
    ++m_depth;
    if (m_depth < kMaxDepth) {
        for (const FrontendEntity &c : e.children) {
            if (c.type != u"keep")
                mapInto(c, &a.children);
        }
    }
    --m_depth;
    return a;
}

void FrontendActionMapper::mapInto(const FrontendEntity &e, QList<LaunchAction> *out)
{
    const QString &t = e.type;
    if (ignoredTypes().contains(t))
        return;
    if (t == u"node" || t == u"lifecycle_node") {
        *out << node(e, Kind::Node);
    } else if (t == u"node_container") {
        *out << node(e, Kind::ComposableContainer);
    } else if (t == u"load_composable_node") {
        LaunchAction a = start(e, Kind::LoadComposableNodes);
        a.target = value(e, QStringLiteral("target"), true);
        for (const FrontendEntity *c : e.childrenOfType(QStringLiteral("composable_node")))
            a.children << composableNode(*c);
        *out << a;
    } else if (t == u"include") {
        LaunchAction a = start(e, Kind::Include);
        a.path = value(e, QStringLiteral("file"), true);
        for (const FrontendEntity *arg : e.childrenOfType(QStringLiteral("arg")))
            a.arguments << qMakePair(value(*arg, QStringLiteral("name"), true),
                                     value(*arg, QStringLiteral("value"), true));
        *out << a;
    } else if (t == u"group" || t == u"timer" || t == u"ros_timer") {
        *out << group(e);
    } else if (t == u"push-ros-namespace" || t == u"push_ros_namespace") {
        LaunchAction a = start(e, Kind::PushNamespace);
        a.nameSpace = value(e, QStringLiteral("namespace"), true);
        *out << a;
    } else if (t == u"remap" || t == u"set_remap") {
        LaunchAction a = start(e, Kind::SetRemap);
        a.remaps << LaunchRemap{value(e, QStringLiteral("from"), true),
                                value(e, QStringLiteral("to"), true), e.evidence};
        *out << a;
    } else if (t == u"set_parameter" || t == u"set_use_sim_time" ||
               t == u"set_parameters_from_file") {
        LaunchAction a = start(e, Kind::SetParameter);
        LaunchParameter p;
        p.evidence = e.evidence;
        if (t == u"set_parameters_from_file") {
            p.isFile = true;
            p.value = value(e, QStringLiteral("filename"), true);
        } else {
            p.name = t == u"set_use_sim_time"
                         ? Substitution::literal(QStringLiteral("use_sim_time"))
                         : value(e, QStringLiteral("name"), true);
            p.value = value(e, QStringLiteral("value"), true);
        }
        a.parameters << p;
        *out << a;
    } else if (t == u"arg") {
        LaunchAction a = start(e, Kind::DeclareArgument);
        const FrontendAttribute *name = e.attribute(QStringLiteral("name"));
        if (!name)
            report(QStringLiteral("missing-attribute"),
                   QStringLiteral("<arg> has no 'name' attribute."), e.evidence);
        a.name = Substitution::literal(name ? name->value : QString()); // names are not parsed
        const FrontendAttribute *def = e.attribute(QStringLiteral("default"));
        if (!def)
            def = e.attribute(QStringLiteral("value")); // ROS 1 style: a fixed value
        if (def) {
            a.value = value(e, *def);
            a.hasValue = true;
        }
        if (const FrontendAttribute *d = e.attribute(QStringLiteral("description")))
            a.description = d->value;
        *out << a;
    } else if (t == u"let") {
        LaunchAction a = start(e, Kind::SetLaunchConfiguration);
        a.name = value(e, QStringLiteral("name"), true);
        a.value = value(e, QStringLiteral("value"), true);
        a.hasValue = true;
        *out << a;
    } else {
        // executable, shutdown, reset, anything unknown: kept visible, not interpreted.
        LaunchAction a = start(e, Kind::Unresolved);
        a.expression = t;
        *out << a;
    }
}

} // namespace rosarch
