// The launch API for the launch-file evaluator: launch and launch_ros calls become
// LaunchActions, substitution calls become Substitutions.
#include "launch/python/pythonlaunchapi.h"
#include "launch/python/pythonlaunchevaluator.h"

#include "syntax/pythonsyntax.h"

#include <QHash>

#include <functional>

namespace rosarch::pylaunch {

namespace {
bool oneOf(const QString &name, std::initializer_list<const char *> names)
{
    for (const char *n : names)
        if (name == QLatin1String(n))
            return true;
    return false;
}

bool given(const Value *v)
{
    return v && v->type != Value::Type::None;
}

Substitution withKind(Substitution::Kind kind, const QString &text = {},
                      QList<Substitution> parts = {})
{
    Substitution s;
    s.kind = kind;
    s.text = text;
    s.parts = std::move(parts);
    return s;
}

/// PythonExpression / $(eval): the parts as written, adjacent literals folded.
Substitution evaluation(const QList<Substitution> &parts)
{
    const Substitution joined = concatenate(parts);
    return withKind(Substitution::Kind::Eval, {},
                    joined.kind == Substitution::Kind::Concat ? joined.parts
                                                              : QList<Substitution>{joined});
}

QList<Substitution> partsOf(const Value &v)
{
    QList<Substitution> parts;
    if (v.type == Value::Type::List)
        for (const Value &item : v.items())
            parts << item.toSubstitution();
    else
        parts << v.toSubstitution();
    return parts;
}

QString nameText(const Value &v)
{
    return v.type == Value::Type::String ? v.text : v.toSubstitution().describe();
}

const QLatin1String kQuote("'");
} // namespace

PythonLaunchApi::PythonLaunchApi(PythonLaunchContext &ctx, PythonLaunchEvaluator &interpreter)
    : m_ctx(ctx), m_interpreter(interpreter)
{
}

QString PythonLaunchApi::textOfCall(TSNode call) const
{
    return oneLine(m_ctx.tree.text(call));
}

std::optional<Value> PythonLaunchApi::callSubstitutionApi(const QString &name, const CallArgs &args,
                                                          TSNode call)
{
    using K = Substitution::Kind;
    const Value *a0 = args.get(0);
    if (oneOf(name, {"LaunchConfiguration", "LaunchConfigAsBool"})) {
        const Value *var = args.get(0, {"variable_name"});
        if (!var)
            return std::nullopt;
        Substitution s = Substitution::configuration(nameText(*var));
        if (const Value *d = args.get(1, {"default"}); given(d))
            s.parts << d->toSubstitution();
        return Value::substitution(s);
    }
    if (name == QLatin1String("EnvironmentVariable")) {
        const Value *var = args.get(0, {"name"});
        if (!var)
            return std::nullopt;
        Substitution s = withKind(K::EnvironmentVariable, nameText(*var));
        if (const Value *d = args.get(1, {"default_value"}); given(d))
            s.parts << d->toSubstitution();
        return Value::substitution(s);
    }
    if (oneOf(name,
              {"FindPackageShare", "get_package_share_directory", "get_package_share_path"})) {
        const Value *p = args.get(0, {"package", "package_name"});
        return p ? std::optional(Value::substitution(
                       withKind(K::FindPackageShare, {}, {p->toSubstitution()})))
                 : std::nullopt;
    }
    if (oneOf(name, {"FindPackagePrefix", "get_package_prefix", "FindPackage"})) {
        const Value *p = args.get(0, {"package", "package_name"});
        return p ? std::optional(Value::substitution(
                       withKind(K::FindPackagePrefix, {}, {p->toSubstitution()})))
                 : std::nullopt;
    }
    if (name == QLatin1String("PathJoinSubstitution")) {
        const Value *list = args.get(0, {"substitutions"});
        return list ? std::optional(Value::substitution(withKind(K::PathJoin, {}, partsOf(*list))))
                    : std::nullopt;
    }
    if (oneOf(name, {"ThisLaunchFileDir", "ThisDir"}))
        return Value::substitution(withKind(K::ThisLaunchFileDir));
    if (name == QLatin1String("ThisLaunchFile"))
        return Value::substitution(withKind(K::ThisLaunchFile));
    if (name == QLatin1String("PythonExpression")) {
        const Value *e = args.get(0, {"expression"});
        return e ? std::optional(Value::substitution(evaluation(partsOf(*e)))) : std::nullopt;
    }
    if (name == QLatin1String("TextSubstitution")) {
        const Value *t = args.get(0, {"text"});
        return t ? Value::substitution(t->toSubstitution()) : Value::string(QString());
    }
    if (oneOf(name, {"EqualsSubstitution", "NotEqualsSubstitution", "AndSubstitution",
                     "OrSubstitution"})) {
        const Value *l = args.get(0, {"left"}), *r = args.get(1, {"right"});
        if (!l || !r)
            return std::nullopt;
        static const QHash<QString, QString> functions{
            {QStringLiteral("EqualsSubstitution"), QStringLiteral("equals")},
            {QStringLiteral("NotEqualsSubstitution"), QStringLiteral("not-equals")},
            {QStringLiteral("AndSubstitution"), QStringLiteral("and")},
            {QStringLiteral("OrSubstitution"), QStringLiteral("or")}};
        return Value::substitution(Substitution::function(
            functions.value(name), {l->toSubstitution(), r->toSubstitution()}));
    }
    if (name == QLatin1String("NotSubstitution") && a0)
        return Value::substitution(
            Substitution::function(QStringLiteral("not"), {a0->toSubstitution()}));
    if (oneOf(name, {"AllSubstitution", "AnySubstitution"})) {
        QList<Substitution> all;
        for (int i = 0; const Value *v = args.get(i); ++i)
            all << v->toSubstitution();
        return Value::substitution(Substitution::function(
            name.startsWith(QLatin1String("All")) ? QStringLiteral("all") : QStringLiteral("any"),
            all));
    }
    if (name == QLatin1String("IfElseSubstitution")) {
        const Value *c = args.get(0, {"condition"});
        const Value *t = args.get(1, {"if_value"}), *e = args.get(2, {"else_value"});
        if (!c)
            return std::nullopt;
        QList<Substitution> parts{c->toSubstitution(), given(t) ? t->toSubstitution()
                                                                : Substitution::literal(QString())};
        if (given(e))
            parts << e->toSubstitution();
        return Value::substitution(Substitution::function(QStringLiteral("if"), parts));
    }
    if (name == QLatin1String("RewrittenYaml")) { // nav2_common: a parameter file rewritten
        const Value *source = args.get(0, {"source_file"});
        if (!source)
            return std::nullopt;
        Substitution s = withKind(K::RewrittenYaml, {}, {source->toSubstitution()});
        const Value *root = args.get(2, {"root_key"});
        s.parts << (given(root) ? root->toSubstitution() : Substitution());
        if (const Value *rewrites = args.get(1, {"param_rewrites"});
            given(rewrites) && rewrites->type == Value::Type::Dict) {
            for (const auto &[key, value] : rewrites->dict->entries)
                s.parts << key.toSubstitution() << value.toParameterValue();
        }
        // value_rewrites replace values, not keys: their keys are marked with a leading '='
        if (const Value *rewrites = args.get(4, {"value_rewrites"});
            given(rewrites) && rewrites->type == Value::Type::Dict) {
            for (const auto &[key, value] : rewrites->dict->entries)
                s.parts << concatenate(
                               {Substitution::literal(QStringLiteral("=")), key.toSubstitution()})
                        << value.toParameterValue();
        }
        return Value::substitution(s);
    }
    if (oneOf(name, {"ParameterFile", "ParameterValue"})) {
        const Value *v = args.get(0, {"param_file", "value"});
        return v ? *v : Value::unknown(textOfCall(call), m_ctx.tree.evidence(call));
    }
    if (oneOf(name, {"IfCondition", "UnlessCondition"})) {
        const Value *e = args.get(0, {"predicate_expression"});
        Value c;
        c.type = Value::Type::Condition;
        c.condition.expression = e ? e->toSubstitution() : Substitution::unknown(textOfCall(call));
        c.condition.unless = name == QLatin1String("UnlessCondition");
        c.condition.text = textOfCall(call);
        return c;
    }
    if (oneOf(name, {"LaunchConfigurationEquals", "LaunchConfigurationNotEquals"})) {
        const Value *var = args.get(0, {"launch_configuration_name"});
        const Value *expected = args.get(1, {"expected_value"});
        if (!var)
            return std::nullopt;
        const QString op = name.contains(QLatin1String("Not")) ? QStringLiteral("' != '")
                                                               : QStringLiteral("' == '");
        Value c;
        c.type = Value::Type::Condition;
        c.condition.expression =
            evaluation({Substitution::literal(kQuote), Substitution::configuration(nameText(*var)),
                        Substitution::literal(op),
                        expected ? expected->toSubstitution() : Substitution::literal(QString()),
                        Substitution::literal(kQuote)});
        c.condition.text = textOfCall(call);
        return c;
    }
    if (oneOf(name, {"PythonLaunchDescriptionSource", "XMLLaunchDescriptionSource",
                     "YAMLLaunchDescriptionSource", "AnyLaunchDescriptionSource",
                     "FrontendLaunchDescriptionSource"})) {
        const Value *path = args.get(0, {"launch_file_path"});
        if (!path)
            return std::nullopt;
        Value s;
        s.type = Value::Type::Source;
        s.subst = path->toSubstitution();
        return s;
    }
    return std::nullopt;
}

LaunchCondition PythonLaunchApi::condition(const CallArgs &args) const
{
    const Value *c = args.get(-1, {"condition"});
    if (!given(c))
        return {};
    if (c->type == Value::Type::Condition)
        return c->condition;
    LaunchCondition unknown;
    unknown.text = oneLine(m_ctx.tree.text(args.node(-1, {"condition"})));
    unknown.expression = Substitution::unknown(unknown.text);
    return unknown;
}

QList<LaunchRemap> PythonLaunchApi::remaps(const Value &value, const Evidence &evidence) const
{
    QList<LaunchRemap> out;
    for (const Value &item : value.items()) {
        const QList<Value> pair = item.items();
        if (pair.size() == 2)
            out << LaunchRemap{pair.at(0).toSubstitution(), pair.at(1).toSubstitution(), evidence};
    }
    return out;
}

QList<LaunchParameter> PythonLaunchApi::parameters(const Value &value,
                                                   const Evidence &evidence) const
{
    QList<LaunchParameter> out;
    std::function<void(const Value &, const Substitution &)> addDict =
        [&](const Value &dict, const Substitution &prefix) {
            for (const auto &e : dict.dict->entries) {
                Substitution name = e.first.toSubstitution();
                if (!prefix.isEmpty())
                    name = concatenate({prefix, Substitution::literal(QStringLiteral(".")), name});
                if (e.second.type == Value::Type::Dict)
                    addDict(e.second, name); // nested dictionaries are dotted names (launch_ros)
                else
                    out << LaunchParameter{name, e.second.toParameterValue(), false, evidence};
            }
        };
    for (const Value &item :
         value.type == Value::Type::List ? value.items() : QList<Value>{value}) {
        if (item.type == Value::Type::Dict)
            addDict(item, Substitution());
        else if (item.type != Value::Type::None && item.type != Value::Type::Skip)
            out << LaunchParameter{Substitution(), item.toSubstitution(), true, evidence};
    }
    return out;
}

void PythonLaunchApi::readNodeFields(LaunchAction &a, const CallArgs &args,
                                     const Evidence &evidence) const
{
    auto read = [&](Substitution &field, std::initializer_list<const char *> names) {
        if (const Value *v = args.get(-1, names); given(v))
            field = v->toSubstitution();
    };
    read(a.package, {"package"});
    read(a.executable, {"executable", "node_executable"});
    read(a.plugin, {"plugin", "node_plugin"});
    read(a.name, {"name", "node_name"});
    read(a.nameSpace, {"namespace", "node_namespace"});
    if (const Value *p = args.get(-1, {"parameters"}); given(p))
        a.parameters = parameters(*p, evidence);
    if (const Value *r = args.get(-1, {"remappings"}); given(r))
        a.remaps = remaps(*r, evidence);
    if (const Value *list = args.get(-1, {"arguments"}); given(list))
        for (const Value &word : list->items())
            a.commandLine << word.toSubstitution();
    // `-r from:=to` in the node's command-line arguments
    for (const char *key : {"arguments", "ros_arguments"}) {
        const Value *list = args.get(-1, {key});
        if (!given(list))
            continue;
        const QList<Value> items = list->items();
        for (qsizetype i = 0; i + 1 < items.size(); ++i) {
            const Value &flag = items.at(i), &rule = items.at(i + 1);
            if (flag.type != Value::Type::String ||
                !(flag.text == QLatin1String("-r") || flag.text == QLatin1String("--remap")))
                continue;
            if (rule.type != Value::Type::String || !rule.text.contains(QLatin1String(":=")))
                continue;
            const QString from = rule.text.section(QLatin1String(":="), 0, 0);
            const Substitution to =
                Substitution::literal(rule.text.section(QLatin1String(":="), 1));
            if (from == u"__ns" || from == u"__node" || from == u"__name")
                (from == u"__ns" ? a.nameSpace : a.name) = to; // rcl: the command line wins
            else if (!from.startsWith(QLatin1String("__")))
                a.remaps << LaunchRemap{Substitution::literal(from), to, evidence};
        }
    }
    // `remappings=[('__node', 'x')]` renames the node unless `name=` does (launch_ros puts the
    // name first, and rcl applies the first matching rule)
    for (qsizetype i = 0; i < a.remaps.size();) {
        const LaunchRemap &r = a.remaps.at(i);
        const QString from = r.from.isLiteral() ? r.from.text : QString();
        if (from == u"__ns" || from == u"__node" || from == u"__name") {
            Substitution &target = from == u"__ns" ? a.nameSpace : a.name;
            if (target.isEmpty())
                target = r.to;
            a.remaps.removeAt(i);
        } else {
            ++i;
        }
    }
}

Value PythonLaunchApi::makeNode(const QString &name, const CallArgs &args, TSNode call)
{
    LaunchAction a;
    a.evidence = m_ctx.tree.evidence(call);
    if (name == QLatin1String("ComposableNodeContainer"))
        a.kind = LaunchAction::Kind::ComposableContainer;
    else if (name == QLatin1String("ComposableNode"))
        a.kind = LaunchAction::Kind::ComposableNode;
    else
        a.kind = LaunchAction::Kind::Node;
    a.lifecycle = name.startsWith(QLatin1String("Lifecycle"));
    readNodeFields(a, args, a.evidence);
    if (const Value *nodes = args.get(-1, {"composable_node_descriptions"}); given(nodes))
        a.children = toActions(*nodes);
    a.condition = condition(args);
    return Value::action({a});
}

Value PythonLaunchApi::makeInclude(const CallArgs &args, TSNode call)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::Include;
    a.evidence = m_ctx.tree.evidence(call);
    if (const Value *source = args.get(0, {"launch_description_source"}))
        a.path = source->toSubstitution();
    if (const Value *arguments = args.get(1, {"launch_arguments"}); given(arguments)) {
        if (arguments->type == Value::Type::Dict) {
            for (const auto &e : arguments->dict->entries)
                a.arguments.append({e.first.toSubstitution(), e.second.toSubstitution()});
        } else {
            for (const Value &item : arguments->items()) {
                const QList<Value> pair = item.items();
                if (pair.size() == 2)
                    a.arguments.append({pair.at(0).toSubstitution(), pair.at(1).toSubstitution()});
            }
        }
    }
    a.condition = condition(args);
    return Value::action({a});
}

Value PythonLaunchApi::makeOpaque(const QString &name, const CallArgs &args, TSNode call)
{
    const Evidence evidence = m_ctx.tree.evidence(call);
    const Value *function = args.get(name == QLatin1String("ForEach") ? 1 : 0, {"function"});
    TSNode functionNode = args.node(name == QLatin1String("ForEach") ? 1 : 0, {"function"});
    LaunchAction unresolved;
    unresolved.kind = LaunchAction::Kind::Unresolved;
    unresolved.evidence = evidence;
    unresolved.expression =
        QStringLiteral("%1(%2)").arg(name, oneLine(m_ctx.tree.text(functionNode)));
    unresolved.condition = condition(args);
    QList<LaunchAction> out{unresolved};
    if (!function || function->type != Value::Type::Function)
        return Value::action(out);

    // Best effort: what the function returns when called with a symbolic context.
    CallArgs callArgs;
    if (name == QLatin1String("OpaqueFunction")) {
        Value context;
        context.type = Value::Type::Context;
        callArgs.positional << context;
        if (const Value *extra = args.get(-1, {"args"}); given(extra))
            callArgs.positional += extra->items();
        if (const Value *kwargs = args.get(-1, {"kwargs"});
            given(kwargs) && kwargs->type == Value::Type::Dict)
            for (const auto &e : kwargs->dict->entries)
                callArgs.keywords.append({e.first.text, e.second});
    } else if (!ts::is(function->node, "lambda")) {
        for (const py::Parameter &p : py::parameters(m_ctx.tree, function->node))
            callArgs.keywords.append({p.name, Value::unknown(p.name)});
    }
    const Value result = m_interpreter.callFunction(*function, callArgs, call);
    if (result.type != Value::Type::List && result.type != Value::Type::Action)
        return Value::action(out);
    LaunchAction group;
    group.kind = LaunchAction::Kind::Group;
    group.scoped = false;
    group.evidence = evidence;
    group.condition = unresolved.condition;
    group.children = toActions(result);
    if (!group.children.isEmpty())
        out << group;
    return Value::action(out);
}

std::optional<Value> PythonLaunchApi::callLaunchApi(const QString &name, const CallArgs &args,
                                                    TSNode call)
{
    using K = LaunchAction::Kind;
    if (std::optional<Value> s = callSubstitutionApi(name, args, call))
        return s;
    const Evidence evidence = m_ctx.tree.evidence(call);
    auto make = [&](K kind) {
        LaunchAction a;
        a.kind = kind;
        a.evidence = evidence;
        a.condition = condition(args);
        return a;
    };

    if (name == QLatin1String("LaunchDescription")) {
        Value ld = m_ctx.newList({});
        ld.list->launchDescription = true;
        if (const Value *entities = args.get(0, {"initial_entities"}); given(entities)) {
            if (entities->type == Value::Type::List) {
                ld.list->items = entities->list->items;
                ld.list->guards = entities->list->guards;
            } else {
                m_ctx.append(ld, *entities);
            }
        }
        return ld;
    }
    if (oneOf(name, {"Node", "LifecycleNode", "ComposableNodeContainer", "ComposableNode"}))
        return makeNode(name, args, call);
    if (name == QLatin1String("IncludeLaunchDescription"))
        return makeInclude(args, call);
    if (oneOf(name, {"OpaqueFunction", "ForEach"}))
        return makeOpaque(name, args, call);
    if (name == QLatin1String("LoadComposableNodes")) {
        LaunchAction a = make(K::LoadComposableNodes);
        if (const Value *target = args.get(-1, {"target_container"}); given(target)) {
            const bool container = target->type == Value::Type::Action &&
                                   !target->actions->isEmpty() &&
                                   target->actions->first().kind == K::ComposableContainer;
            a.target = container ? target->actions->first().name : target->toSubstitution();
        }
        if (const Value *nodes = args.get(-1, {"composable_node_descriptions"}); given(nodes))
            a.children = toActions(*nodes);
        return Value::action({a});
    }
    if (oneOf(name, {"GroupAction", "TimerAction"})) {
        LaunchAction a = make(K::Group);
        const Value *actions = args.get(name == QLatin1String("GroupAction") ? 0 : -1, {"actions"});
        if (name == QLatin1String("TimerAction")) {
            a.scoped = false;
        } else if (const Value *scoped = args.get(-1, {"scoped"});
                   scoped && scoped->truth().has_value()) {
            a.scoped = *scoped->truth();
        }
        if (const Value *configs = args.get(-1, {"launch_configurations"});
            given(configs) && configs->type == Value::Type::Dict) {
            for (const auto &e : configs->dict->entries) {
                LaunchAction set = make(K::SetLaunchConfiguration);
                set.condition = {};
                set.name = e.first.toSubstitution();
                set.value = e.second.toSubstitution();
                set.hasValue = true;
                a.children << set;
            }
        }
        if (given(actions))
            a.children += toActions(*actions);
        return Value::action({a});
    }
    if (oneOf(name, {"PushRosNamespace", "PushROSNamespace"})) {
        LaunchAction a = make(K::PushNamespace);
        if (const Value *ns = args.get(0, {"namespace"}))
            a.nameSpace = ns->toSubstitution();
        return Value::action({a});
    }
    if (name == QLatin1String("SetRemap")) {
        LaunchAction a = make(K::SetRemap);
        const Value *src = args.get(0, {"src"}), *dst = args.get(1, {"dst"});
        a.remaps << LaunchRemap{src ? src->toSubstitution() : Substitution(),
                                dst ? dst->toSubstitution() : Substitution(), evidence};
        return Value::action({a});
    }
    if (oneOf(name, {"SetParameter", "SetUseSimTime"})) {
        LaunchAction a = make(K::SetParameter);
        const bool simTime = name == QLatin1String("SetUseSimTime");
        const Value *n = simTime ? nullptr : args.get(0, {"name"});
        const Value *v = args.get(simTime ? 0 : 1, {"value"});
        a.parameters << LaunchParameter{
            simTime ? Substitution::literal(QStringLiteral("use_sim_time"))
                    : (n ? n->toSubstitution() : Substitution()),
            v ? v->toParameterValue() : Substitution(), false, evidence};
        return Value::action({a});
    }
    if (name == QLatin1String("SetParametersFromFile")) {
        LaunchAction a = make(K::SetParameter);
        const Value *f = args.get(0, {"filename"});
        a.parameters << LaunchParameter{Substitution(), f ? f->toSubstitution() : Substitution(),
                                        true, evidence};
        return Value::action({a});
    }
    if (name == QLatin1String("DeclareLaunchArgument")) {
        LaunchAction a = make(K::DeclareArgument);
        if (const Value *n = args.get(0, {"name"}))
            a.name = n->toSubstitution();
        if (const Value *d = args.get(1, {"default_value"}); given(d)) {
            a.value = d->toSubstitution();
            a.hasValue = true;
        }
        if (const Value *d = args.get(2, {"description"}); given(d))
            a.description =
                d->type == Value::Type::String ? d->text : d->toSubstitution().describe();
        return Value::action({a});
    }
    if (name == QLatin1String("SetLaunchConfiguration")) {
        LaunchAction a = make(K::SetLaunchConfiguration);
        if (const Value *n = args.get(0, {"name"}))
            a.name = n->toSubstitution();
        if (const Value *v = args.get(1, {"value"})) {
            a.value = v->toSubstitution();
            a.hasValue = true;
        }
        return Value::action({a});
    }
    if (name == QLatin1String("RegisterEventHandler")) {
        LaunchAction a = make(K::Unresolved);
        a.expression = textOfCall(call);
        QList<LaunchAction> out{a};
        const Value *handler = args.get(0, {"event_handler"});
        if (handler && handler->actions && !handler->actions->isEmpty()) {
            // What the handler starts is still part of the system, only later.
            LaunchAction group = make(K::Group);
            group.scoped = false;
            group.children = *handler->actions;
            out << group;
        }
        return Value::action(out);
    }
    if (oneOf(name,
              {"OnProcessExit", "OnProcessStart", "OnExecutionComplete", "OnStateTransition"})) {
        Value handler = Value::unknown(textOfCall(call), evidence);
        QList<LaunchAction> started;
        for (const char *key : {"on_exit", "on_start", "on_completion", "entities"})
            if (const Value *v = args.get(-1, {key}); given(v) && v->type != Value::Type::Function)
                started += toActions(*v);
        handler.actions = std::make_shared<const QList<LaunchAction>>(started);
        return handler;
    }
    // Harmless for the architecture: recorded as nothing.
    if (oneOf(name, {"LogInfo", "SetEnvironmentVariable", "AppendEnvironmentVariable",
                     "PrependEnvironmentVariable", "UnsetEnvironmentVariable", "SetROSLogDir",
                     "EmitEvent", "Shutdown"}))
        return Value::skip();
    return std::nullopt;
}

} // namespace rosarch::pylaunch
