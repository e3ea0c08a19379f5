#include "launch/launchexecutor.h"
#include "core/rosnames.h"
#include "launch/substitutionevaluator.h"

#include <QFileInfo>
#include <QSet>
#include <algorithm>

namespace rosarch {

QString formatName(LaunchFileDescription::Format f)
{
    switch (f) {
    case LaunchFileDescription::Format::Python:
        return QStringLiteral("python");
    case LaunchFileDescription::Format::Xml:
        return QStringLiteral("xml");
    case LaunchFileDescription::Format::Yaml:
        return QStringLiteral("yaml");
    }
    return {};
}

namespace {

QString nsKey(const QString &ns)
{
    return ns.isEmpty() ? QStringLiteral("/") : ns;
}

/// Whether a namespace joined onto one that may rest on a guess rests on one.
bool joinedNamespaceGuessed(bool outerGuessed, const QString &inner, bool innerGuessed)
{
    // An absolute namespace replaces the one around it, a guess and all.
    return innerGuessed || (outerGuessed && !inner.trimmed().startsWith(QLatin1Char('/')));
}

} // namespace

QString launchFileDir(const QString &file)
{
    const qsizetype slash = file.lastIndexOf(QLatin1Char('/'));
    return slash < 0 ? QString() : file.left(slash);
}

QString joinNamespace(const QString &outer, const QString &inner)
{
    QString in = inner.trimmed();
    if (in.startsWith(QLatin1Char('/')))
        return in == QLatin1String("/") ? QString() : in;
    if (in.isEmpty())
        return outer;
    while (in.endsWith(QLatin1Char('/')))
        in.chop(1);
    return outer + QLatin1Char('/') + in;
}

LaunchExecutor::LaunchExecutor(const Workspace &workspace, const AtomicNodeList &nodes,
                               Loader loader, LaunchDependencies *out)
    : m_workspace(workspace), m_load(std::move(loader)), m_out(out), m_classes(nodes),
      m_modelled(workspace.root)
{
    for (const RosPackage &p : workspace.packages)
        m_packagePaths.insert(p.name, p.path);
    for (const SourceFile &f : workspace.files)
        m_filePackages.insert(f.path, f.package); // the last of a path, as a scan would find
}

void LaunchExecutor::runRoot(const QString &file, const QMap<QString, QString> &arguments,
                             const QString &nameSpace)
{
    const LaunchFileDescription *d = m_load(file);
    if (!d)
        return;
    LaunchFileInstance inst;
    inst.id = (m_idPrefix + QStringLiteral("lf%1")).arg(m_out->instances.size() + 1);
    inst.type = QFileInfo(file).fileName();
    inst.file = file;
    inst.package = m_filePackages.value(file);
    inst.format = formatName(d->format);
    inst.evidence = Evidence::startOf(file);
    m_out->instances.append(inst);

    Scope scope;
    scope.configurations = arguments;
    scope.nameSpace = nameSpace;
    Frame frame;
    frame.instance = int(m_out->instances.size()) - 1;
    frame.file = file;
    frame.chain = QStringList{file};
    frame.root = true;
    execute(d->actions, scope, frame, 0);
    for (auto it = arguments.cbegin(); it != arguments.cend(); ++it)
        m_out->instances[frame.instance].arguments.append({it.key(), it.value()});
}

QStringList LaunchExecutor::directIncludes(const QString &file, QStringList *conditional)
{
    QStringList includes;
    const LaunchFileDescription *d = m_load(file);
    if (!d)
        return includes;
    Scope scope;
    Frame frame;
    frame.file = file;
    frame.chain = QStringList{file};
    frame.collectOnly = true;
    frame.includes = &includes;
    frame.conditionalIncludes = conditional;
    execute(d->actions, scope, frame, 0);
    return includes;
}

QString LaunchExecutor::evaluate(const Substitution &s, const Scope &scope, const Frame &frame,
                                 QList<Unresolved> *unresolved, const Evidence &evidence,
                                 bool *guessed) const
{
    const SubstitutionEvaluator eval(scope.configurations, launchFileDir(frame.file),
                                     &scope.guessed);
    SubstitutionEvaluator::Result r = eval.evaluate(s);
    if (guessed)
        *guessed = !r.isResolved();
    for (Unresolved &u : r.unresolved) {
        u.evidence = evidence;
        if (u.kind == QLatin1String(SubstitutionEvaluator::kEvaluationLimit))
            m_budget.sayValueLimit(m_out, evidence);
        if (u.guess.isEmpty())
            u.guess = r.value;
        if (unresolved)
            unresolved->append(u);
    }
    return r.value;
}

bool LaunchExecutor::conditionHolds(const LaunchAction &a, const Scope &scope, const Frame &frame,
                                    QList<Unresolved> *unresolved, bool *undecided) const
{
    if (!a.condition.isSet())
        return true;
    const SubstitutionEvaluator eval(scope.configurations, launchFileDir(frame.file),
                                     &scope.guessed);
    QList<Unresolved> found;
    bool holds = eval.isTrue(a.condition.expression, &found);
    if (!found.isEmpty()) {
        for (Unresolved &u : found) {
            u.evidence = a.evidence;
            u.expression = a.condition.text.isEmpty() ? u.expression : a.condition.text;
        }
        if (unresolved)
            unresolved->append(found);
        if (undecided)
            *undecided = true;
        return true; // undecidable: keep it (the best guess), marked unresolved
    }
    return a.condition.unless ? !holds : holds;
}

LaunchExecutor::ContainerName::ContainerName(const QString &target, const QString &nameSpace)
    : m_target(target), m_scoped(target.isEmpty() ? QString() : joinNamespace(nameSpace, target))
{
}

bool LaunchExecutor::ContainerName::matches(const NodeInstance &n) const
{
    if (m_target.isEmpty())
        return false;
    if (n.nodeName == m_target)
        return true;
    // The length of joinNamespace(namespace, name): another length matches no target.
    QStringView name = QStringView(n.nodeName).trimmed();
    qsizetype length = 0;
    if (name.startsWith(u'/')) {
        length = name == u"/" ? 0 : name.size();
    } else if (name.isEmpty()) {
        length = n.nameSpace.size();
    } else {
        while (name.endsWith(u'/'))
            name.chop(1);
        length = n.nameSpace.size() + 1 + name.size();
    }
    if (length != m_target.size() && length != m_scoped.size())
        return false;
    const QString fq = joinNamespace(n.nameSpace, n.nodeName);
    return fq == m_target || fq == m_scoped;
}

void LaunchExecutor::configure(Scope &scope, const QString &name, const QString &value,
                               bool guessed)
{
    scope.configurations.insert(name, value);
    if (guessed)
        scope.guessed.insert(name);
    else
        scope.guessed.remove(name);
}

void LaunchExecutor::appendRemaps(const QList<LaunchRemap> &rules, const Scope &scope,
                                  const Frame &frame, QList<Unresolved> *unresolved,
                                  QList<QPair<QString, QString>> *remaps,
                                  QList<int> *guessedRemaps) const
{
    for (const LaunchRemap &r : rules) {
        const QString from = evaluate(r.from, scope, frame, unresolved, r.evidence);
        bool guessed = false;
        const QString to = evaluate(r.to, scope, frame, unresolved, r.evidence, &guessed);
        if (guessed)
            guessedRemaps->append(int(remaps->size()));
        remaps->append({from, to});
    }
}

void LaunchExecutor::addToNamespace(int instance, const QString &ns, const QString &id)
{
    if (instance >= 0)
        m_out->instances[instance].namespaces[nsKey(ns)].append(id);
}

void LaunchExecutor::noteDoubledNamespace(const QString &pushed, bool guessed, const Scope &scope,
                                          const Frame &frame, const Evidence &evidence)
{
    QString in = pushed.trimmed();
    while (in.endsWith(QLatin1Char('/')))
        in.chop(1);
    const Evidence &outer = scope.namespacePush;
    if (frame.instance < 0 || frame.collectOnly || guessed || scope.guessedNamespace ||
        in.isEmpty() || in.startsWith(QLatin1Char('/')) || outer.file.isEmpty() ||
        outer.file == evidence.file ||
        !(scope.nameSpace == QLatin1Char('/') + in ||
          scope.nameSpace.endsWith(QLatin1Char('/') + in)))
        return;
    m_doubled.append({m_out->instances[frame.instance].id, in, joinNamespace(scope.nameSpace, in),
                      evidence, outer});
}

void LaunchExecutor::execute(const QList<LaunchAction> &actions, Scope &scope, Frame &frame,
                             int depth)
{
    auto unresolvedSink = [&]() -> QList<Unresolved> * {
        return frame.instance >= 0 ? &m_out->instances[frame.instance].unresolved : nullptr;
    };
    for (const LaunchAction &a : actions) {
        switch (a.kind) {
        case LaunchAction::Kind::DeclareArgument: {
            const QString name = evaluate(a.name, scope, frame, nullptr, a.evidence);
            if (frame.root && !frame.collectOnly) {
                LaunchArgument arg;
                arg.name = name;
                arg.hasDefault = a.hasValue;
                arg.defaultValue =
                    a.hasValue ? evaluate(a.value, scope, frame, nullptr, a.evidence) : QString();
                arg.description = a.description;
                arg.launchFile = frame.file;
                arg.evidence = a.evidence;
                m_out->arguments.append(arg);
            }
            if (scope.configurations.contains(name))
                break; // given by the person or by the including file
            if (a.hasValue) {
                bool guessed = false;
                const QString value =
                    evaluate(a.value, scope, frame, unresolvedSink(), a.evidence, &guessed);
                configure(scope, name, value, guessed);
            } else if (!frame.collectOnly && frame.instance >= 0) {
                m_out->instances[frame.instance].unresolved.append(
                    {QStringLiteral("argument"),
                     QStringLiteral("launch argument '%1' has no default").arg(name), QString(),
                     a.evidence});
            }
            break;
        }
        case LaunchAction::Kind::SetLaunchConfiguration: {
            const QString name = evaluate(a.name, scope, frame, nullptr, a.evidence);
            bool guessed = false;
            const QString value =
                evaluate(a.value, scope, frame, unresolvedSink(), a.evidence, &guessed);
            configure(scope, name, value, guessed);
            break;
        }
        case LaunchAction::Kind::PushNamespace:
            if (conditionHolds(a, scope, frame, unresolvedSink())) {
                bool guessed = false;
                const QString pushed =
                    evaluate(a.nameSpace, scope, frame, unresolvedSink(), a.evidence, &guessed);
                noteDoubledNamespace(pushed, guessed, scope, frame, a.evidence);
                scope.guessedNamespace =
                    joinedNamespaceGuessed(scope.guessedNamespace, pushed, guessed);
                scope.nameSpace = joinNamespace(scope.nameSpace, pushed);
                scope.namespacePush = a.evidence;
            }
            break;
        case LaunchAction::Kind::SetRemap:
            appendRemaps(a.remaps, scope, frame, unresolvedSink(), &scope.remaps,
                         &scope.guessedRemaps);
            break;
        case LaunchAction::Kind::SetParameter:
            for (const LaunchParameter &p : a.parameters)
                scope.parameters.append(
                    {p.isFile ? QString() : evaluate(p.name, scope, frame, nullptr, p.evidence),
                     evaluate(p.value, scope, frame, unresolvedSink(), p.evidence),
                     QStringLiteral("launch"), QString(), p.evidence});
            break;
        case LaunchAction::Kind::Group: {
            Scope inner = scope;
            bool undecided = false;
            const bool holds = conditionHolds(a, scope, frame, unresolvedSink(), &undecided);
            if (a.condition.isSet() && !frame.collectOnly && frame.instance >= 0)
                m_out->instances[frame.instance].groups.append(
                    {a.condition.text, a.condition.unless, holds, undecided, a.evidence});
            inner.active = scope.active && holds;
            inner.activeByGuess = scope.activeByGuess || undecided;
            if (!inner.active && frame.collectOnly && !frame.conditionalIncludes)
                break;
            execute(a.children, inner, frame, depth + 1);
            // A group whose condition is false never runs its actions: its `let`s and pushes
            // stay inside, whether it is scoped or not.
            if (!a.scoped && holds) {
                const bool active = scope.active;
                scope = inner;
                scope.active = active;
            }
            break;
        }
        case LaunchAction::Kind::Node:
            if (!frame.collectOnly)
                executeNode(a, scope, frame, QString());
            break;
        case LaunchAction::Kind::ComposableContainer: {
            if (frame.collectOnly)
                break;
            executeNode(a, scope, frame, QString());
            const QString containerId = m_out->nodes.last().id;
            Scope inner = scope;
            inner.active = m_out->nodes.last().active;
            inner.activeByGuess = m_out->nodes.last().activeByGuess;
            for (const LaunchAction &c : a.children)
                executeNode(c, inner, frame, containerId);
            break;
        }
        case LaunchAction::Kind::LoadComposableNodes: {
            if (frame.collectOnly)
                break;
            QList<Unresolved> *sink = unresolvedSink();
            const QString target = evaluate(a.target, scope, frame, sink, a.evidence);
            // The container is found by its name (plain or fully qualified).
            QString containerId = target;
            bool found = false;
            const ContainerName name(target, scope.nameSpace);
            for (const NodeInstance &n : std::as_const(m_out->nodes))
                if (name.matches(n)) {
                    containerId = n.id;
                    found = true;
                }
            Scope inner = scope;
            bool undecided = false;
            inner.active = scope.active && conditionHolds(a, scope, frame, sink, &undecided);
            inner.activeByGuess = scope.activeByGuess || undecided;
            const qsizetype first = m_out->nodes.size();
            for (const LaunchAction &c : a.children)
                executeNode(c, inner, frame, containerId);
            if (m_unfound && !found && !target.isEmpty() && m_out->nodes.size() > first)
                m_unfound->append({first, m_out->nodes.size(), target, scope.nameSpace});
            break;
        }
        case LaunchAction::Kind::Include:
            executeInclude(a, scope, frame, depth);
            break;
        case LaunchAction::Kind::ComposableNode:
            if (!frame.collectOnly)
                executeNode(a, scope, frame, QString());
            break;
        case LaunchAction::Kind::Unresolved:
            if (frame.instance >= 0)
                m_out->instances[frame.instance].unresolved.append(
                    {a.expression.startsWith(QLatin1String("OpaqueFunction"))
                         ? QStringLiteral("opaque-function")
                         : QStringLiteral("action"),
                     a.expression, QString(), a.evidence});
            break;
        }
    }
}

void LaunchExecutor::executeNode(const LaunchAction &a, const Scope &scope, Frame &frame,
                                 const QString &container)
{
    if (m_budget.overBudget(m_out, a.evidence))
        return;
    NodeInstance n;
    n.id = (m_idPrefix + QStringLiteral("n%1")).arg(m_out->nodes.size() + 1);
    n.launchFileId = m_out->instances[frame.instance].id;
    n.evidence = a.evidence;
    n.lifecycle = a.lifecycle;
    n.container = container;
    QList<Unresolved> &u = n.unresolved;
    n.package = evaluate(a.package, scope, frame, &u, a.evidence);
    const bool composable = a.kind == LaunchAction::Kind::ComposableNode;
    n.execName = evaluate(composable ? a.plugin : a.executable, scope, frame, &u, a.evidence);
    const QString launchName = evaluate(a.name, scope, frame, &u, a.evidence, &n.guessedName);
    n.namedByLaunch = !launchName.isEmpty();
    bool nsGuessed = false;
    const QString ns = evaluate(a.nameSpace, scope, frame, &u, a.evidence, &nsGuessed);
    // A container's namespace names the container only: its components run in the scope's.
    if (a.kind != LaunchAction::Kind::ComposableContainer)
        noteDoubledNamespace(ns, nsGuessed, scope, frame, a.evidence);
    n.nameSpace = nsKey(joinNamespace(scope.nameSpace, ns));
    n.guessedNamespace = joinedNamespaceGuessed(scope.guessedNamespace, ns, nsGuessed);
    n.condition = a.condition.text;
    bool undecided = false;
    n.active = scope.active && conditionHolds(a, scope, frame, &u, &undecided);
    const bool launchGuess = scope.activeByGuess || undecided;
    n.activeByGuess = launchGuess;
    if (a.condition.isSet() && !n.active)
        n.active = false;
    QList<const AtomicNode *> classes = m_classes.started(n.package, n.execName, composable);
    QString builtBy;
    if (classes.isEmpty() && !composable && a.kind == LaunchAction::Kind::Node &&
        !n.execName.isEmpty() && !NodeClasses::declares(m_workspace.package(n.package), n.execName))
        classes = m_classes.elsewhere(n.execName, &builtBy);
    if (!builtBy.isEmpty()) {
        Diagnostic diag;
        diag.severity = Diagnostic::Severity::Info;
        diag.code = QStringLiteral("executable-in-other-package");
        diag.message = QStringLiteral("The executable %1 is started as part of package %2, which "
                                      "does not build it; package %3 of the workspace does, so "
                                      "the instance is typed by its class.")
                           .arg(n.execName, n.package, builtBy);
        diag.evidence = a.evidence;
        m_out->diagnostics.append(diag);
    }
    // What the process runs: one node per class, or, for an executable that builds its nodes
    // in its own code, one per construction there (blueprint §1, "Nodes built in code").
    const QList<NodeClasses::Start> starts =
        NodeClasses::starts(classes, composable ? QString() : n.execName);
    // The executable's own system (its action is the build file's line, run from its main
    // source): each node is where the code constructs it.
    const bool ownSystem = a.evidence.file != frame.file;
    const auto nodeNameOf = [&](const NodeClasses::Start &s) {
        if (!launchName.isEmpty())
            return launchName;
        return s.second && !s.second->nodeName.isEmpty() ? s.second->nodeName : s.first->nodeName;
    };
    if (const AtomicNode *cls = classes.value(0)) {
        n.className = cls->className;
        n.classId = cls->id;
        n.lifecycle = n.lifecycle || cls->lifecycle;
        n.nodeKind = composable ? QStringLiteral("composable") : compileTypeName(cls->compileType);
        n.nodeName = nodeNameOf(starts.front());
        if (starts.front().second)
            n.constructedPorts = starts.front().second->ports;
        if (starts.front().second && ownSystem) // where main() builds it
            n.evidence = starts.front().second->evidence;
        // built under an `if` of its main: it may be one of alternatives
        n.activeByGuess =
            n.activeByGuess || (starts.front().second && !starts.front().second->guard.isEmpty());
    } else {
        n.nodeName = launchName;
        if (classes.isEmpty() && !m_workspace.package(n.package)) { // code outside
            QStringList commandLine;
            for (const Substitution &word : a.commandLine)
                commandLine << evaluate(word, scope, frame, nullptr, a.evidence);
            m_modelled.forNode(
                &n, commandLine, a.evidence,
                [&](const QString &path) { return resolveInclude(path, frame.file).file; },
                &m_out->diagnostics);
        }
        if (composable) {
            n.nodeKind = QStringLiteral("composable");
        } else if (a.kind == LaunchAction::Kind::ComposableContainer) {
            n.nodeKind = QStringLiteral("cpp"); // component containers are C++ processes
        } else if (const RosPackage *p = m_workspace.package(n.package)) {
            n.nodeKind = p->buildType == QLatin1String("ament_python") ? QStringLiteral("python")
                                                                       : QStringLiteral("cpp");
        }
    }
    n.remaps = scope.remaps;
    n.guessedRemaps = scope.guessedRemaps;
    appendRemaps(a.remaps, scope, frame, &u, &n.remaps, &n.guessedRemaps);
    for (const ParameterSetting &p : scope.parameters)
        n.parameters.append({p.name, p.value});
    for (const LaunchParameter &p : a.parameters)
        n.parameters.append({p.isFile ? QString() : evaluate(p.name, scope, frame, &u, p.evidence),
                             evaluate(p.value, scope, frame, &u, p.evidence)});
    n.effectiveParameters = effectiveParameters(a, scope, frame, n, classes.value(0), &u);
    n.plugins = pluginsOf(n.effectiveParameters);
    m_out->instances[frame.instance].nodes.append(n.id);
    addToNamespace(frame.instance, n.nameSpace, n.id);
    m_out->nodes.append(n);
    if (!classes.isEmpty())
        addChildNodes(n, *classes.front(), a, scope, frame, 0);
    // An executable whose main spins several nodes starts one instance of each.
    for (qsizetype k = 1; k < starts.size(); ++k) {
        const AtomicNode *cls = starts[k].first;
        NodeInstance more = n;
        more.id = (m_idPrefix + QStringLiteral("n%1")).arg(m_out->nodes.size() + 1);
        more.className = cls->className;
        more.classId = cls->id;
        more.lifecycle = a.lifecycle || cls->lifecycle;
        more.nodeName = nodeNameOf(starts[k]);
        more.constructedPorts = starts[k].second ? starts[k].second->ports : QList<Port>();
        if (starts[k].second && ownSystem)
            more.evidence = starts[k].second->evidence;
        more.activeByGuess =
            launchGuess || (starts[k].second && !starts[k].second->guard.isEmpty());
        QList<Unresolved> reported; // the same launch line: already on `n`
        more.effectiveParameters = effectiveParameters(a, scope, frame, more, cls, &reported);
        more.plugins = pluginsOf(more.effectiveParameters);
        m_out->instances[frame.instance].nodes.append(more.id);
        addToNamespace(frame.instance, more.nameSpace, more.id);
        m_out->nodes.append(more);
        addChildNodes(more, *cls, a, scope, frame, 0);
    }
}

// A child node runs in its parent's process: the launch action's remaps and parameter files
// apply to it as to every node of the process, matched by its own fully qualified name.
void LaunchExecutor::addChildNodes(const NodeInstance &parent, const AtomicNode &cls,
                                   const LaunchAction &a, const Scope &scope, const Frame &frame,
                                   int depth)
{
    if (cls.children.isEmpty())
        return;
    if (depth >= kMaxChildDepth) {
        Diagnostic diag;
        diag.severity = Diagnostic::Severity::Warning;
        diag.code = QStringLiteral("child-depth");
        diag.message = QStringLiteral("Stopped following the nodes that %1 creates inside itself "
                                      "(bound: %2 generations of child nodes).")
                           .arg(cls.className)
                           .arg(kMaxChildDepth);
        diag.evidence = cls.children.front().evidence;
        m_out->diagnostics.append(diag);
        return;
    }
    for (const ChildNode &c : cls.children) {
        const AtomicNode *childClass = m_classes.node(c.className);
        if (!childClass)
            continue;
        // In the parent's process: its launch file, condition, container, remaps and parameters.
        NodeInstance n = parent;
        n.id = (m_idPrefix + QStringLiteral("n%1")).arg(m_out->nodes.size() + 1);
        n.parentNode = parent.id;
        n.nodeKind = compileTypeName(childClass->compileType);
        n.package = childClass->packageName;
        n.className = childClass->className;
        n.classId = childClass->id;
        n.lifecycle = childClass->lifecycle;
        n.nodeName = c.nodeName.isEmpty() ? childClass->nodeName : c.nodeName;
        n.guessedName = false; // named in code
        const QString outer = parent.nameSpace == QLatin1String("/") ? QString() : parent.nameSpace;
        n.nameSpace = nsKey(joinNamespace(outer, c.nameSpace));
        n.unresolved.clear(); // the launch line's: on the parent
        n.evidence = c.evidence;
        QList<Unresolved> reported;
        n.effectiveParameters = effectiveParameters(a, scope, frame, n, childClass, &reported);
        n.plugins = pluginsOf(n.effectiveParameters);
        m_out->instances[frame.instance].nodes.append(n.id);
        addToNamespace(frame.instance, n.nameSpace, n.id);
        m_out->nodes.append(n);
        addChildNodes(n, *childClass, a, scope, frame, depth + 1);
    }
}

} // namespace rosarch
