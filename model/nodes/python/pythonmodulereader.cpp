#include "nodes/python/pythonmodulereader.h"
#include "nodes/python/pythonparameterreader.h"

#include "syntax/pythonsyntax.h"

#include <algorithm>

namespace rosarch {

namespace {
// Calls that build a node without a class of its own, and whether it is a lifecycle node.
const std::pair<const char *, bool> kNodeFactories[] = {
    {"rclpy.create_node", false},
    {"rclpy.node.Node", false},
    {"rclpy.lifecycle.Node", true},
    {"rclpy.lifecycle.LifecycleNode", true},
    {"rclpy.lifecycle.node.LifecycleNode", true},
};

enum
{
    ClassDefinition,
    FunctionDefinition,
    Call,
    Assignment
};
// The types the walks over every node of a scope look for, told apart by symbol.
const ts::TypeSet &scopeKinds()
{
    static const ts::TypeSet kinds(
        SyntaxTree::Grammar::Python,
        {"class_definition", "function_definition", "call", "assignment"});
    return kinds;
}

// `kind` is scopeKinds().index(n).
bool skipInScope(int kind, TSNode n, TSNode body, bool moduleLevel)
{
    if (kind != ClassDefinition && kind != FunctionDefinition)
        return false;
    if (ts_node_eq(n, body))
        return false;
    return kind == ClassDefinition || moduleLevel;
}

} // namespace

/// The calls and the assignments of a scope's body, in the order a walk over it meets them,
/// without the nested scopes its passes skip (skipInScope): one walk for the passes over it.
struct PythonModuleReader::ScopeNodes
{
    std::vector<TSNode> calls;
    std::vector<TSNode> assignments;

    ScopeNodes(TSNode body, bool moduleLevel)
    {
        const ts::TypeSet &kinds = scopeKinds();
        py::walk(body, [&](TSNode n) {
            const int kind = kinds.index(n);
            if (skipInScope(kind, n, body, moduleLevel))
                return false;
            if (kind == Call)
                calls.push_back(n);
            else if (kind == Assignment)
                assignments.push_back(n);
            return true;
        });
    }
};

namespace {

/// "std_msgs.msg.String", "pkg.srv.T.Request": a message, service or action type.
bool isInterfaceName(const QString &dotted)
{
    return dotted.contains(QLatin1String(".msg.")) || dotted.contains(QLatin1String(".srv.")) ||
           dotted.contains(QLatin1String(".action."));
}

PythonHandle parameterHandle(int index, const QString &name, const QString &method = {})
{
    PythonHandle h;
    h.kind = PythonHandle::Kind::Parameter;
    h.index = index;
    h.name = name;
    h.method = method;
    return h;
}

bool isSuperCall(const SyntaxTree &tree, TSNode n)
{
    return ts::is(n, "call") && tree.view(ts::field(n, "function")) == "super";
}

/// py_trees' setup protocol: `def setup(self, node=None, **kwargs)` receives the node that the
/// tree hands over, as its `node` parameter or as `kwargs['node']` / `kwargs.get('node')`.
void addSetupHandles(const SyntaxTree &tree, TSNode method, QHash<QString, PythonHandle> *handles)
{
    PythonHandle setup;
    setup.kind = PythonHandle::Kind::Setup;
    for (const py::Parameter &p : py::parameters(tree, method))
        if (p.name == QLatin1String("node"))
            handles->insert(p.name, setup);
    for (TSNode p : ts::namedChildren(ts::field(method, "parameters"))) {
        TSNode splat = ts::is(p, "typed_parameter") ? ts_node_named_child(p, 0) : p;
        if (!ts::is(splat, "dictionary_splat_pattern"))
            continue;
        const QString kwargs = tree.text(ts_node_named_child(splat, 0));
        for (const char *form : {"%1['node']", "%1[\"node\"]", "%1.get('node')", "%1.get(\"node\")",
                                 "%1.get('node',None)", "%1.get(\"node\",None)"})
            handles->insert(QString::fromLatin1(form).arg(kwargs), setup);
    }
}
} // namespace

PythonModuleReader::PythonModuleReader(const SyntaxTree &tree, QString modulePath)
    : m_tree(tree), m_resolver(tree, std::move(modulePath)), m_ports(m_resolver)
{
}

PythonModuleFacts PythonModuleReader::read(const QString &package) const
{
    PythonModuleFacts facts;
    facts.file = m_tree.file();
    facts.package = package;
    facts.modulePath = m_resolver.modulePath();
    const ts::TypeSet &kinds = scopeKinds();
    py::walk(m_tree.root(), [&](TSNode n) {
        const int kind = kinds.index(n);
        if (kind == ClassDefinition)
            facts.classes.append(readClass(n));
        else if (kind == FunctionDefinition && m_resolver.scopes().isTopLevel(n))
            facts.functions.append(readFunction(n));
        return true;
    });
    facts.functions.append(readModuleStatements());
    const PythonParameterReader parameters(m_tree);
    if (parameters.acceptsUndeclared(m_tree.root())) {
        for (PythonClassFacts &c : facts.classes)
            c.acceptsUndeclared = true;
        for (PythonFunctionFacts &f : facts.functions)
            f.acceptsUndeclared = true;
    }
    return facts;
}

QString PythonModuleReader::key(TSNode expr) const
{
    QString text = m_tree.text(expr);
    text.remove(QLatin1Char(' '));
    return text;
}

QList<PythonParameter> PythonModuleReader::parameters(TSNode function, bool skipSelf) const
{
    QList<PythonParameter> out;
    const auto params = py::parameters(m_tree, function);
    for (size_t i = skipSelf ? 1 : 0; i < params.size(); ++i) {
        PythonParameter p;
        p.name = params[i].name;
        p.hasDefault = !ts::isNull(params[i].defaultValue);
        if (p.hasDefault) {
            p.defaultIsString =
                PythonResolver::stringLiteral(m_tree, params[i].defaultValue, &p.defaultValue);
            if (!p.defaultIsString)
                p.defaultValue = m_tree.text(params[i].defaultValue);
        }
        out.append(p);
    }
    return out;
}

QList<PythonArgument> PythonModuleReader::arguments(TSNode call, const QStringList &parameterNames,
                                                    bool skipFirst) const
{
    QList<PythonArgument> out;
    bool skipped = !skipFirst;
    for (TSNode n : ts::namedChildren(ts::field(call, "arguments"))) {
        const std::string_view t = ts::type(n);
        if (t == "comment" || t == "dictionary_splat")
            continue;
        if (t == "list_splat")
            break;
        PythonArgument a;
        TSNode value = n;
        if (t == "keyword_argument") {
            a.keyword = m_tree.text(ts::field(n, "name"));
            value = ts::field(n, "value");
        } else if (!skipped) {
            skipped = true;
            continue;
        }
        a.text = m_tree.text(value);
        const PythonValue v = m_resolver.value(value);
        a.isString = v.origin != NameOrigin::Expression;
        a.origin = v.origin;
        a.parameter = v.parameter;
        if (a.isString)
            a.value = v.value;
        if (ts::is(value, "identifier")) {
            a.parameterIndex = int(parameterNames.indexOf(a.text));
            if (!a.isString)
                a.items = m_resolver.loopItems(value);
        }
        if (py::isDottedName(value)) {
            const QString type = m_resolver.interfaceType(value);
            if (type.contains(QLatin1Char('/')))
                a.interfaceType = type;
        }
        out.append(a);
    }
    return out;
}

bool PythonModuleReader::proceduralNode(TSNode expr, PythonProcedural *procedural) const
{
    if (!ts::is(expr, "call"))
        return false;
    const QString target = m_resolver.qualifiedName(ts::field(expr, "function"));
    if (target.isEmpty())
        return false;
    for (const auto &[factory, lifecycle] : kNodeFactories) {
        if (target != QLatin1String(factory))
            continue;
        TSNode name = py::argument(m_tree, expr, 0, "node_name");
        // A name the code computes is the run's to decide: unresolved, never a variable's name.
        if (!PythonResolver::stringLiteral(m_tree, name, &procedural->nodeName))
            procedural->nodeName.clear();
        procedural->lifecycle = lifecycle;
        return true;
    }
    return false;
}

void PythonModuleReader::findAliases(const ScopeNodes &body, Receivers *receivers, bool members,
                                     const QString &function, TSNode evidence,
                                     PythonScopeFacts *facts, const Receivers &visible) const
{
    const bool moduleLevel = ts::isNull(evidence);
    for (const TSNode n : body.assignments) {
        TSNode left = ts::field(n, "left");
        TSNode right = ts::field(n, "right");
        if (members
                ? !(ts::is(left, "attribute") && m_tree.view(ts::field(left, "object")) == "self")
                : !ts::is(left, "identifier"))
            continue;
        PythonProcedural procedural;
        if (proceduralNode(right, &procedural)) {
            procedural.function = function;
            procedural.evidence = m_tree.evidence(moduleLevel ? n : evidence);
            facts->procedurals.append(procedural);
            PythonHandle h;
            h.kind = PythonHandle::Kind::Procedural;
            h.index = int(facts->procedurals.size() - 1);
            receivers->insert(key(left), h);
            continue;
        }
        const QString from = key(right);
        if (receivers->contains(from))
            receivers->insert(key(left), receivers->value(from));
        else if (visible.contains(from))
            receivers->insert(key(left), visible.value(from));
    }
}

void PythonModuleReader::scan(const ScopeNodes &body, const Receivers &receivers,
                              const QString &method, const QStringList &parameterNames,
                              PythonScopeFacts *facts) const
{
    for (const TSNode n : body.calls) {
        PortKind kind;
        TSNode receiver;
        if (m_ports.recognize(n, &kind, &receiver)) {
            const auto it = receivers.constFind(key(receiver));
            if (it == receivers.constEnd())
                continue;
            PythonPortFact fact;
            fact.port = m_ports.read(n, kind);
            fact.method = method;
            fact.handle = it.value();
            // a name passed in through the constructor or function (directly or kept in a
            // member) can be resolved per call site
            auto parameterRef = [&](TSNode argument) {
                PythonParameterRef ref;
                const auto source = receivers.constFind(key(argument));
                if (source != receivers.constEnd() && source->kind == PythonHandle::Kind::Parameter)
                    ref = {source->index, source->name, source->method};
                return ref;
            };
            fact.nameFrom = parameterRef(m_ports.nameArgument(n, kind));
            fact.typeFrom = parameterRef(m_ports.typeArgument(n, kind));
            // a name built from parts (f-string, format, +): literal where all parts are known,
            // else a template that each call site completes
            QList<PythonNamePart> parts;
            if (!fact.nameFrom.isValid() && fact.port.nameOrigin == NameOrigin::Expression &&
                nameParts(m_ports.nameArgument(n, kind), 0, &parts)) {
                const bool literal =
                    std::all_of(parts.cbegin(), parts.cend(),
                                [](const PythonNamePart &p) { return !p.from.isValid(); });
                if (literal) {
                    fact.port.name.clear();
                    for (const PythonNamePart &p : parts)
                        fact.port.name += p.text;
                    fact.port.nameOrigin = NameOrigin::Local;
                } else {
                    fact.nameParts = parts;
                }
            }
            facts->ports.append(fact);
            continue;
        }
        TSNode function = ts::field(n, "function");
        QString target;
        if (py::isDottedName(function)) {
            target = m_resolver.qualifiedName(function);
        } else if (ts::is(function, "attribute")) {
            // `Helper(...).attach(self)`: a method of an object built on the spot
            TSNode object = ts::field(function, "object");
            if (ts::is(object, "call") && py::isDottedName(ts::field(object, "function")))
                target = m_resolver.qualifiedName(ts::field(object, "function")) +
                         QLatin1Char('.') + m_tree.text(ts::field(function, "attribute"));
        }
        if (target.isEmpty())
            continue;
        // builtins (print, len, ...) and message constructors cannot take a node handle apart
        const bool external = !target.contains(QLatin1Char('.')) || isInterfaceName(target);
        int position = 0;
        for (TSNode a : ts::namedChildren(ts::field(n, "arguments"))) {
            const std::string_view t = ts::type(a);
            if (t == "comment" || t == "dictionary_splat")
                continue;
            if (t == "list_splat")
                break;
            const bool named = t == "keyword_argument";
            const auto it = external ? receivers.constEnd()
                                     : receivers.constFind(key(named ? ts::field(a, "value") : a));
            if (it != receivers.constEnd()) {
                PythonHandoff h;
                h.target = target;
                h.argument = named ? -1 : position;
                if (named)
                    h.keyword = m_tree.text(ts::field(a, "name"));
                h.handle = it.value();
                h.method = method;
                h.arguments = arguments(n, parameterNames, false);
                h.evidence = m_tree.evidence(n);
                facts->handoffs.append(h);
            }
            if (!named)
                ++position;
        }
        if (m_tree.view(function).substr(0, 5) != "self.") {
            PythonCall call;
            call.target = target;
            // arguments of workspace functions too: they may pass on what builds a helper
            if (!external)
                call.arguments = arguments(n, parameterNames, false);
            call.evidence = m_tree.evidence(n);
            facts->calls.append(call);
        }
    }
}

PythonClassFacts PythonModuleReader::readClass(TSNode cls) const
{
    PythonClassFacts facts;
    facts.name = m_tree.text(ts::field(cls, "name"));
    const QString &module = m_resolver.modulePath();
    facts.qualifiedName = module.isEmpty() ? facts.name : module + QLatin1Char('.') + facts.name;
    facts.evidence = m_tree.evidence(cls);
    for (TSNode b : ts::namedChildren(ts::field(cls, "superclasses"))) {
        const std::string_view t = ts::type(b);
        if (t == "keyword_argument" || t == "comment" || t == "list_splat" ||
            t == "dictionary_splat")
            continue;
        facts.bases.append(m_tree.text(b));
        const QString q = m_resolver.qualifiedName(b);
        facts.baseTargets.append(q.isEmpty() ? m_tree.text(b) : q);
    }

    std::vector<TSNode> methods;
    for (TSNode child : ts::namedChildren(ts::field(cls, "body"))) {
        TSNode def = py::undecorated(child);
        if (ts::is(def, "function_definition")) {
            methods.push_back(def);
            facts.methods.append(m_tree.text(ts::field(def, "name")));
            facts.methodParameters.append(parameters(def, true));
        }
    }

    // Each method's body walked once, for the passes below.
    std::vector<ScopeNodes> bodies;
    bodies.reserve(methods.size());
    for (const TSNode method : methods)
        bodies.emplace_back(ts::field(method, "body"), false);

    // How the constructor calls the base constructor, and which overrides call their base.
    for (size_t i = 0; i < methods.size(); ++i) {
        const QString &name = facts.methods.at(qsizetype(i));
        const bool isInit = name == QLatin1String("__init__");
        QStringList parameterNames;
        if (isInit) {
            facts.hasInit = true;
            facts.initParameters = parameters(methods[i], true);
            for (const PythonParameter &p : facts.initParameters)
                parameterNames.append(p.name);
        }
        for (const TSNode n : bodies[i].calls) {
            TSNode function = ts::field(n, "function");
            if (!ts::is(function, "attribute") ||
                m_tree.text(ts::field(function, "attribute")) != name)
                continue;
            TSNode object = ts::field(function, "object");
            const bool viaSuper = isSuperCall(m_tree, object);
            if (!viaSuper && !facts.bases.contains(key(object)))
                continue;
            if (!facts.superCalledMethods.contains(name))
                facts.superCalledMethods.append(name);
            if (isInit && !facts.hasBaseInitCall) {
                facts.hasBaseInitCall = true;
                facts.baseInitArguments = arguments(n, parameterNames, !viaSuper);
            }
        }
    }

    // Node handles held in members: `self.node = node` (constructor parameter) or
    // `self.node = rclpy.create_node(...)`.
    Receivers members;
    for (size_t i = 0; i < methods.size(); ++i) {
        Receivers visible;
        const auto params = py::parameters(m_tree, methods[i]);
        if (!params.empty())
            visible.insert(params.front().name, PythonHandle{});
        if (facts.methods.at(qsizetype(i)) == QLatin1String("__init__")) {
            for (size_t p = 1; p < params.size(); ++p)
                visible.insert(params[p].name, parameterHandle(int(p - 1), params[p].name));
        } else if (facts.methods.at(qsizetype(i)) == QLatin1String("setup")) {
            addSetupHandles(m_tree, methods[i], &visible);
        }
        findAliases(bodies[i], &members, true, facts.methods.at(qsizetype(i)), methods[i], &facts,
                    visible);
    }

    for (size_t i = 0; i < methods.size(); ++i) {
        const QString &name = facts.methods.at(qsizetype(i));
        Receivers receivers = members;
        const auto params = py::parameters(m_tree, methods[i]);
        QStringList parameterNames;
        if (!params.empty())
            receivers.insert(params.front().name, PythonHandle{});
        const bool isInit = name == QLatin1String("__init__");
        for (size_t p = 1; p < params.size(); ++p) {
            parameterNames.append(params[p].name);
            receivers.insert(params[p].name, parameterHandle(int(p - 1), params[p].name,
                                                             isInit ? QString() : name));
        }
        if (name == QLatin1String("setup"))
            addSetupHandles(m_tree, methods[i], &receivers);
        findAliases(bodies[i], &receivers, false, name, methods[i], &facts, {});
        scan(bodies[i], receivers, name, parameterNames, &facts);
    }
    const PythonParameterReader declared(m_tree);
    facts.parameterDeclarations = declared.read(ts::field(cls, "body"));
    facts.acceptsUndeclared = declared.acceptsUndeclared(cls);
    return facts;
}

PythonFunctionFacts PythonModuleReader::readFunction(TSNode function) const
{
    PythonFunctionFacts facts;
    facts.name = m_tree.text(ts::field(function, "name"));
    facts.parameters = parameters(function, false);
    facts.evidence = m_tree.evidence(function);
    Receivers receivers;
    QStringList parameterNames;
    for (int i = 0; i < facts.parameters.size(); ++i) {
        const QString &p = facts.parameters.at(i).name;
        parameterNames.append(p);
        receivers.insert(p, parameterHandle(i, p));
    }
    const ScopeNodes body(ts::field(function, "body"), false);
    findAliases(body, &receivers, false, facts.name, function, &facts, {});
    scan(body, receivers, QString(), parameterNames, &facts);
    facts.parameterDeclarations = PythonParameterReader(m_tree).read(function);
    return facts;
}

PythonFunctionFacts PythonModuleReader::readModuleStatements() const
{
    PythonFunctionFacts facts;
    Receivers receivers;
    const ScopeNodes module(m_tree.root(), true);
    findAliases(module, &receivers, false, QString(), TSNode{}, &facts, {});
    scan(module, receivers, QString(), {}, &facts);
    return facts;
}

} // namespace rosarch
