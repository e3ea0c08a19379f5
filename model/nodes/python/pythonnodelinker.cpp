#include "nodes/python/pythonnodelinker.h"

#include "nodes/python/pythonbinding.h"
#include "nodes/python/pythonentrypoints.h"

#include <QFileInfo>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace rosarch {

using PythonBinding::argumentAt;
using PythonBinding::substituteName;

namespace {
constexpr int kMaxDepth = PythonSetupProtocol::kMaxDepth;

// rclpy's node classes as reached through imports, and whether they are lifecycle nodes.
const std::pair<const char *, bool> kRosNodeBases[] = {
    {"rclpy.node.Node", false},
    {"rclpy.Node", false},
    {"rclpy.lifecycle.Node", true},
    {"rclpy.lifecycle.LifecycleNode", true},
    {"rclpy.lifecycle.node.LifecycleNode", true},
};

int rosNodeBase(const QString &target)
{
    for (const auto &[name, lifecycle] : kRosNodeBases)
        if (target == QLatin1String(name))
            return lifecycle ? 2 : 1;
    return 0;
}

bool portLess(const Port &a, const Port &b)
{
    return std::tie(a.evidence.file, a.evidence.line, a.evidence.column, a.via) <
           std::tie(b.evidence.file, b.evidence.line, b.evidence.column, b.via);
}

QList<Port> sortedUnique(QList<Port> ports)
{
    std::stable_sort(ports.begin(), ports.end(), portLess);
    QList<Port> out;
    for (const Port &p : ports) {
        // a helper built twice creates the same port twice; one is enough for the architecture
        const bool seen = std::any_of(out.cbegin(), out.cend(), [&](const Port &q) {
            return q.evidence == p.evidence && q.kind == p.kind && q.name == p.name;
        });
        if (!seen)
            out.append(p);
    }
    return out;
}
// `super().__init__(zone + '_watcher')`: a name joined from string literals and constructor
// parameters, with the arguments of one construction; "" when a piece is anything else.
QString joinedName(const QString &text, const QList<PythonParameter> &parameters,
                   const QList<PythonArgument> &arguments)
{
    static const QRegularExpression quoted(QStringLiteral(R"(^(['"])([^'"\\]*)\1$)"));
    static const QRegularExpression identifier(QStringLiteral(R"(^[A-Za-z_]\w*$)"));
    QString out;
    for (const QString &piece : text.split(u'+')) {
        const QString t = piece.trimmed();
        if (const QRegularExpressionMatch m = quoted.match(t); m.hasMatch()) {
            out += m.captured(2);
            continue;
        }
        if (!identifier.match(t).hasMatch())
            return {};
        int index = -1;
        for (int i = 0; i < parameters.size() && index < 0; ++i)
            if (parameters.at(i).name == t)
                index = i;
        if (index < 0)
            return {};
        const PythonArgument *a = argumentAt(arguments, index, t);
        if (a && a->isString)
            out += a->value;
        else if (!a && parameters.at(index).defaultIsString)
            out += parameters.at(index).defaultValue;
        else
            return {};
    }
    return out;
}

} // namespace

PythonNodeLinker::PythonNodeLinker(const QList<PythonModuleFacts> &modules)
    : m_modules(modules), m_index(modules),
      m_setup(
          m_index, [this](int id) { return nodeKind(id) != NotANode; },
          [this](const PythonHandoff &h, const PythonScopeFacts &from, int depth) {
              return helperPorts(h, from, depth);
          })
{
    auto indexCalls = [&](const PythonScopeFacts &scope) {
        for (const PythonCall &call : scope.calls) {
            const int id = m_index.findClass(call.target);
            if (id >= 0)
                m_instantiations[id].append(&call);
        }
    };
    for (const PythonModuleFacts &module : m_modules) {
        for (const PythonClassFacts &c : module.classes)
            indexCalls(c);
        for (const PythonFunctionFacts &f : module.functions)
            indexCalls(f);
    }
    nameProcedurals();
}

int PythonNodeLinker::nodeKind(int id, int depth) const
{
    const auto it = m_kinds.constFind(id);
    if (it != m_kinds.constEnd())
        return it.value();
    if (depth > kMaxDepth)
        return NotANode;
    m_kinds.insert(id, NotANode); // breaks inheritance cycles
    int kind = NotANode;
    for (const QString &base : m_index.classFacts(id).baseTargets)
        if ((kind = rosNodeBase(base)) != NotANode)
            break;
    if (kind == NotANode) {
        for (int base : m_index.projectBases(id))
            if ((kind = nodeKind(base, depth + 1)) != NotANode)
                break;
    }
    m_kinds.insert(id, kind);
    return kind;
}

QList<PythonNodeLinker::ScopedPort> PythonNodeLinker::classPorts(int id, int depth) const
{
    QList<ScopedPort> out;
    if (depth > kMaxDepth)
        return out;
    const PythonClassFacts &c = m_index.classFacts(id);
    for (const PythonPortFact &f : c.ports) {
        if (f.handle.kind != PythonHandle::Kind::Self)
            continue;
        ScopedPort sp;
        sp.port = f.port;
        sp.method = f.method;
        sp.fact = &f;
        if (!f.nameParts.isEmpty()) {
            // a name built from the parameters of one of the node's methods: their defaults
            const QString method = f.nameParts.first().from.method;
            const qsizetype m =
                c.methods.indexOf(method.isEmpty() ? QStringLiteral("__init__") : method);
            if (m >= 0)
                PythonBinding::applyArguments(&sp.port, f, method, {}, &c.methodParameters.at(m));
        }
        if (f.nameFrom.isValid() && f.nameFrom.method.isEmpty()) {
            sp.parameter = f.nameFrom.index;
            sp.parameterName = f.nameFrom.name;
        }
        out.append(sp);
    }
    for (const PythonHandoff &h : c.handoffs)
        if (h.handle.kind == PythonHandle::Kind::Self)
            for (const Port &p : helperPorts(h, c, depth + 1)) {
                ScopedPort sp;
                sp.port = p;
                sp.method = h.method;
                out.append(sp);
            }
    for (int base : m_index.projectBases(id)) {
        for (ScopedPort sp : classPorts(base, depth + 1)) {
            // an override that does not call the base's version replaces its ports
            if (!sp.method.isEmpty() && c.methods.contains(sp.method) &&
                !c.superCalledMethods.contains(sp.method))
                continue;
            sp.port.inherited = true;
            sp.fact = nullptr; // its parameters are the base's
            // a name taken from the base constructor's parameter: see what this class passes
            if (sp.parameter >= 0 && c.hasInit) {
                const PythonArgument *a =
                    c.hasBaseInitCall
                        ? argumentAt(c.baseInitArguments, sp.parameter, sp.parameterName)
                        : nullptr;
                sp.parameter = -1;
                if (a && a->parameterIndex >= 0) {
                    sp.parameter = a->parameterIndex;
                    sp.parameterName = a->text;
                } else if (a && a->isString) {
                    substituteName(&sp.port, *a);
                }
            }
            out.append(sp);
        }
    }
    return out;
}

QList<Port> PythonNodeLinker::helperPorts(const PythonHandoff &handoff,
                                          const PythonScopeFacts &from, int depth) const
{
    if (depth > kMaxDepth) {
        m_setup.reportBound(handoff.evidence, QStringLiteral("helpers handed the node"));
        return {};
    }
    if (PythonSetupProtocol::isSetupHandoff(handoff))
        return m_setup.setupPorts(handoff, from, depth);
    auto parameterHandle = [&](const QList<PythonParameter> &params, PythonHandle *handle) {
        int index = handoff.argument;
        if (index < 0)
            for (int i = 0; i < params.size() && index < 0; ++i)
                if (params.at(i).name == handoff.keyword)
                    index = i;
        if (index < 0 || index >= params.size())
            return false;
        handle->kind = PythonHandle::Kind::Parameter;
        handle->index = index;
        handle->name = params.at(index).name;
        return true;
    };
    QList<Port> out;
    PythonHandle handle;
    int cls = m_index.findClass(handoff.target);
    // a helper without a constructor of its own takes the node through its base's constructor
    for (int i = 0; i < 4 && cls >= 0 && !m_index.classFacts(cls).hasInit; ++i) {
        const QList<int> bases = m_index.projectBases(cls);
        cls = bases.isEmpty() ? -1 : bases.first();
    }
    const int fn = cls >= 0 ? -1 : m_index.findFunction(handoff.target);
    if (cls >= 0) {
        const PythonClassFacts &c = m_index.classFacts(cls);
        if (parameterHandle(c.initParameters, &handle))
            out = scopePorts(c, handle, c.name, depth, &handoff.arguments, &c.initParameters);
    } else if (fn >= 0) {
        const PythonFunctionFacts &function = m_index.functionFacts(fn);
        if (parameterHandle(function.parameters, &handle))
            out = scopePorts(function, handle, function.name, depth, &handoff.arguments,
                             &function.parameters);
    } else {
        out = methodPorts(handoff, depth);
    }
    for (Port &p : out)
        p.viaEvidence.prepend(handoff.evidence);
    return out;
}

QList<Port> PythonNodeLinker::methodPorts(const PythonHandoff &handoff, int depth) const
{
    // `obj.method(node)` on an object of unknown type: the one workspace class with such a
    // method that takes the node at that position (or the class named, when it is)
    const qsizetype dot = handoff.target.lastIndexOf(QLatin1Char('.'));
    if (dot <= 0)
        return {};
    const QString method = handoff.target.mid(dot + 1);
    // `Helper().attach(node)` names the class
    const int owner = m_index.findClass(handoff.target.left(dot));
    int found = -1;
    PythonHandle handle;
    for (int id = 0; id < m_index.classCount(); ++id) {
        if (owner >= 0 && id != owner)
            continue;
        const PythonClassFacts &c = m_index.classFacts(id);
        const qsizetype m = c.methods.indexOf(method);
        if (m < 0 || method == QLatin1String("__init__"))
            continue;
        const QList<PythonParameter> &params = c.methodParameters.at(m);
        int index = handoff.argument;
        if (index < 0)
            for (int i = 0; i < params.size() && index < 0; ++i)
                if (params.at(i).name == handoff.keyword)
                    index = i;
        if (index < 0 || index >= params.size())
            continue;
        if (found >= 0)
            return {}; // ambiguous
        found = id;
        handle.kind = PythonHandle::Kind::Parameter;
        handle.index = index;
        handle.name = params.at(index).name;
        handle.method = method;
    }
    if (found < 0)
        return {};
    const PythonClassFacts &c = m_index.classFacts(found);
    return scopePorts(c, handle, c.name, depth, &handoff.arguments,
                      &c.methodParameters.at(c.methods.indexOf(method)));
}

QList<Port> PythonNodeLinker::scopePorts(const PythonScopeFacts &scope, const PythonHandle &handle,
                                         const QString &via, int depth,
                                         const QList<PythonArgument> *arguments,
                                         const QList<PythonParameter> *parameters) const
{
    QList<Port> out;
    for (const PythonPortFact &f : scope.ports) {
        if (!f.handle.sameAs(handle))
            continue;
        Port p = f.port;
        if (p.via.isEmpty())
            p.via = via;
        if (arguments)
            PythonBinding::applyArguments(&p, f, handle.method, *arguments, parameters);
        out.append(p);
    }
    for (const PythonHandoff &h : scope.handoffs)
        if (h.handle.sameAs(handle))
            out.append(helperPorts(h, scope, depth + 1));
    return out;
}

PythonNodeLinker::NameInfo PythonNodeLinker::nameInfo(int id, int depth) const
{
    NameInfo info;
    if (depth > kMaxDepth)
        return info;
    const PythonClassFacts &c = m_index.classFacts(id);
    bool direct = false;
    for (const QString &base : c.baseTargets)
        direct = direct || rosNodeBase(base) != NotANode;
    int nodeBase = -1;
    if (!direct)
        for (int b : m_index.projectBases(id))
            if (nodeBase < 0 && nodeKind(b) != NotANode)
                nodeBase = b;
    if (!c.hasInit)
        return nodeBase >= 0 ? nameInfo(nodeBase, depth + 1) : info;
    if (!c.hasBaseInitCall)
        return info;
    auto evaluate = [&](const PythonArgument *a) {
        NameInfo n;
        if (!a)
            return n;
        if (a->parameterIndex >= 0) {
            n.kind = NameInfo::Kind::Parameter;
            n.text = a->text;
            n.index = a->parameterIndex;
            n.owner = id;
        } else if (a->isString) {
            n.kind = NameInfo::Kind::Literal;
            n.text = a->value;
        } else {
            n.kind = NameInfo::Kind::Expression;
            n.text = a->text;
        }
        return n;
    };
    if (direct)
        return evaluate(argumentAt(c.baseInitArguments, 0, QStringLiteral("node_name")));
    if (nodeBase < 0)
        return info;
    const NameInfo base = nameInfo(nodeBase, depth + 1);
    if (base.kind != NameInfo::Kind::Parameter)
        return base;
    if (const PythonArgument *a = argumentAt(c.baseInitArguments, base.index, base.text))
        return evaluate(a);
    const PythonParameter &p = m_index.classFacts(base.owner).initParameters.at(base.index);
    info.kind = p.defaultIsString ? NameInfo::Kind::Literal : NameInfo::Kind::Expression;
    info.text = p.defaultIsString ? p.defaultValue : base.text;
    return info;
}

bool PythonNodeLinker::agreedArgument(int id, int index, const QString &name,
                                      const QString &fallback, PythonArgument *agreed) const
{
    // an instantiation that leaves the parameter out gets the fallback (the default)
    bool unknown = false;
    bool found = false;
    for (const PythonCall *call : m_instantiations.value(id)) {
        const PythonArgument *a = argumentAt(call->arguments, index, name);
        PythonArgument value;
        if (a && a->isString) {
            value = *a;
        } else if (!a && !fallback.isNull()) {
            value.isString = true;
            value.value = fallback;
            value.origin = NameOrigin::Literal;
        } else {
            unknown = true;
            break;
        }
        if (found && value.value != agreed->value) {
            unknown = true;
            break;
        }
        *agreed = value;
        found = true;
    }
    return found && !unknown;
}

QString PythonNodeLinker::nodeName(int id) const
{
    const NameInfo info = nameInfo(id, 0);
    if (info.kind == NameInfo::Kind::Expression)
        return {}; // decided at run time: unresolved, never the expression's text
    if (info.kind != NameInfo::Kind::Parameter)
        return info.text;
    // the name is a constructor parameter: take it from the instantiations when they agree
    const PythonParameter &param = m_index.classFacts(info.owner).initParameters.at(info.index);
    const QString fallback = param.defaultIsString ? param.defaultValue : QString();
    PythonArgument agreed;
    if (agreedArgument(id, info.index, param.name, fallback, &agreed))
        return agreed.value;
    // Instantiations disagree or none is known: the instance decides (unresolved), never the
    // parameter's own name.
    return param.defaultIsString ? param.defaultValue : QString();
}

void PythonNodeLinker::nameProcedurals()
{
    for (const PythonModuleFacts &module : m_modules) {
        QList<Procedural> found;
        auto collect = [&](const PythonScopeFacts &scope, const QString &label) {
            for (int k = 0; k < scope.procedurals.size(); ++k)
                found.append({&module, &scope, k, label, {}, {}});
        };
        for (const PythonClassFacts &c : module.classes)
            collect(c, c.name);
        for (const PythonFunctionFacts &f : module.functions)
            collect(f, f.name.isEmpty() ? QStringLiteral("module") : f.name);
        std::sort(found.begin(), found.end(), [](const Procedural &a, const Procedural &b) {
            const Evidence &ea = a.scope->procedurals.at(a.index).evidence;
            const Evidence &eb = b.scope->procedurals.at(b.index).evidence;
            return std::tie(ea.line, ea.column, a.index) < std::tie(eb.line, eb.column, b.index);
        });
        const QString stem = QFileInfo(module.file).completeBaseName();
        QSet<QString> used;
        for (Procedural &p : found) {
            if (found.size() == 1) {
                p.className = stem;
                p.qualifiedName = module.modulePath;
            } else {
                // procedural nodes of one file are told apart by their class or function
                QString name = stem + QLatin1Char('_') + p.label;
                const QString base = name;
                for (int n = 2; used.contains(name); ++n)
                    name = base + QLatin1Char('_') + QString::number(n);
                used.insert(name);
                p.className = name;
                p.qualifiedName = module.modulePath + QLatin1Char('.') + name.mid(stem.size() + 1);
            }
            m_procedurals.append(p);
        }
    }
}

NodeConstruction PythonNodeLinker::construction(int cls, const PythonCall &call) const
{
    const PythonClassFacts &c = m_index.classFacts(cls);
    NodeConstruction k;
    k.className = c.qualifiedName;
    k.evidence = call.evidence;
    const NameInfo info = nameInfo(cls, 0);
    if (info.kind == NameInfo::Kind::Literal) {
        k.nodeName = info.text;
    } else if (info.kind == NameInfo::Kind::Expression && c.hasBaseInitCall) {
        if (const PythonArgument *a =
                argumentAt(c.baseInitArguments, 0, QStringLiteral("node_name")))
            k.nodeName = joinedName(a->text, c.initParameters, call.arguments);
    } else if (info.kind == NameInfo::Kind::Parameter) {
        const PythonParameter &param = m_index.classFacts(info.owner).initParameters.at(info.index);
        const PythonArgument *a = argumentAt(call.arguments, info.index, param.name);
        if (a && a->isString)
            k.nodeName = a->value;
        else if (!a && param.defaultIsString)
            k.nodeName = param.defaultValue;
    }
    // Only the ports the constructor's arguments name (the others are the class's own)
    for (const ScopedPort &sp : classPorts(cls, 0)) {
        Port p = sp.port;
        if (sp.parameter >= 0) {
            const PythonArgument *a = argumentAt(call.arguments, sp.parameter, sp.parameterName);
            if (!a || !a->isString)
                continue;
            substituteName(&p, *a);
        } else if (sp.fact && !sp.fact->nameParts.isEmpty() &&
                   sp.fact->nameParts.first().from.method.isEmpty()) {
            // `zone + '/occupied'` from the constructor's own parameters
            PythonBinding::applyArguments(&p, *sp.fact, QString(), call.arguments,
                                          &c.initParameters);
        } else {
            continue;
        }
        k.ports.append(p);
    }
    return k;
}

QList<ParameterDeclaration> PythonNodeLinker::declaredParameters(int id) const
{
    QList<ParameterDeclaration> out = m_index.classFacts(id).parameterDeclarations;
    QList<int> bases = m_index.projectBases(id);
    QList<int> seen{id};
    for (qsizetype i = 0; i < bases.size() && i < kMaxDepth; ++i) {
        const int b = bases.at(i);
        if (seen.contains(b))
            continue;
        seen.append(b);
        for (ParameterDeclaration p : m_index.classFacts(b).parameterDeclarations) {
            p.inherited = true;
            out.append(p);
        }
        bases += m_index.projectBases(b);
    }
    QList<ParameterDeclaration> unique;
    QStringList names;
    for (const ParameterDeclaration &p : std::as_const(out))
        if (!names.contains(p.name)) {
            names.append(p.name);
            unique.append(p);
        }
    return unique;
}

bool PythonNodeLinker::acceptsUndeclared(int id, int depth) const
{
    if (m_index.classFacts(id).acceptsUndeclared)
        return true;
    if (depth > kMaxDepth)
        return false;
    for (int b : m_index.projectBases(id))
        if (acceptsUndeclared(b, depth + 1))
            return true;
    return false;
}

void PythonNodeLinker::link(LanguageAnalysis *out) const
{
    QList<AtomicNode> nodes;
    for (int id = 0; id < m_index.classCount(); ++id) {
        const int kind = nodeKind(id);
        if (kind == NotANode)
            continue;
        const PythonClassFacts &c = m_index.classFacts(id);
        const PythonModuleFacts &module = m_index.classModule(id);
        AtomicNode n;
        n.className = c.name;
        n.qualifiedName = c.qualifiedName;
        n.nodeName = nodeName(id);
        n.packageName = module.package;
        n.sourceFiles = {module.file};
        n.compileType = AtomicNode::CompileType::Python;
        n.baseClasses = c.bases;
        n.lifecycle = kind == LifecycleNode;
        n.evidence = c.evidence;
        QList<Port> ports;
        for (ScopedPort sp : classPorts(id, 0)) {
            PythonArgument agreed;
            const QString fallback = sp.port.isResolved() ? sp.port.name : QString();
            if (sp.parameter >= 0 &&
                agreedArgument(id, sp.parameter, sp.parameterName, fallback, &agreed) &&
                agreed.value != sp.port.name)
                substituteName(&sp.port, agreed);
            ports.append(sp.port);
        }
        n.ports = sortedUnique(ports);
        n.parameters = declaredParameters(id);
        n.acceptsUndeclared = acceptsUndeclared(id, 0);
        nodes.append(n);
    }
    for (const Procedural &p : m_procedurals) {
        const PythonProcedural &facts = p.scope->procedurals.at(p.index);
        AtomicNode n;
        n.className = p.className;
        n.qualifiedName = p.qualifiedName;
        n.nodeName = facts.nodeName;
        n.packageName = p.module->package;
        n.sourceFiles = {p.module->file};
        n.compileType = AtomicNode::CompileType::Python;
        n.lifecycle = facts.lifecycle;
        n.procedural = true;
        n.evidence = facts.evidence;
        PythonHandle handle;
        handle.kind = PythonHandle::Kind::Procedural;
        handle.index = p.index;
        n.ports = sortedUnique(scopePorts(*p.scope, handle, QString(), 0));
        n.parameters = p.scope->parameterDeclarations;
        n.acceptsUndeclared = p.scope->acceptsUndeclared;
        nodes.append(n);
    }
    out->diagnostics.append(m_setup.diagnostics());
    std::sort(nodes.begin(), nodes.end(), [](const AtomicNode &a, const AtomicNode &b) {
        return std::tie(a.packageName, a.className, a.qualifiedName, a.evidence.file,
                        a.evidence.line) < std::tie(b.packageName, b.className, b.qualifiedName,
                                                    b.evidence.file, b.evidence.line);
    });
    out->nodes.append(nodes);

    const PythonEntryPoints entryPoints(
        m_index, [this](int cls) { return nodeKind(cls) != NotANode; },
        [this](const PythonScopeFacts *scope) {
            QStringList names;
            for (const Procedural &p : m_procedurals)
                if (p.scope == scope)
                    names.append(p.qualifiedName);
            return names;
        },
        [this](int cls, const PythonCall &call) { return construction(cls, call); });
    entryPoints.addEntryPoints(out);
}

} // namespace rosarch
