#include "nodes/cpp/cppnodelinker.h"

#include "syntax/cppsyntax.h"

#include <QFileInfo>
#include <QHash>
#include <QRegularExpression>
#include <QSet>
#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <functional>
#include <map>
#include <numeric>
#include <optional>

namespace rosarch {

using namespace cppsyntax;

namespace {

QString fileStem(const QString &path)
{
    return QFileInfo(path).completeBaseName();
}

// gtest bodies (TEST, TEST_F) parse as functions named by the macro; their nodes are fixtures.
bool isMacroFunction(const QString &name)
{
    return !name.isEmpty() && name == name.toUpper() && name.at(0).isLetter();
}

// One call can be reached twice (a helper built twice with the same arguments, or through two
// chains of calls): the same port, kept with the first chain. Linear: ports are compared only
// with those of the same name and place (a class with 60,000 ports took minutes before).
void appendUnique(QList<Port> *into, const QList<Port> &ports)
{
    auto placeOf = [](const Port &p) {
        return p.name + QLatin1Char('\n') + p.evidence.file + QLatin1Char(':') +
               QString::number(p.evidence.line) + QLatin1Char(':') +
               QString::number(p.evidence.column);
    };
    QHash<QString, QList<qsizetype>> byPlace;
    for (qsizetype i = 0; i < into->size(); ++i)
        byPlace[placeOf(into->at(i))].append(i);
    for (const Port &p : ports) {
        QList<qsizetype> &same = byPlace[placeOf(p)];
        if (std::any_of(same.cbegin(), same.cend(), [&](qsizetype i) {
                Port copy = p; // the same call reached through another helper: the same port
                copy.viaEvidence = into->at(i).viaEvidence;
                copy.via = into->at(i).via;
                return into->at(i) == copy;
            }))
            continue;
        same.append(into->size());
        into->append(p);
    }
}

} // namespace

CppNodeLinker::CppNodeLinker(const QList<CppFileFacts> &files)
    : m_files(files), m_index(files), m_shared(files, m_index),
      m_names(m_index, m_facts, m_interfaceAliases, m_shared),
      m_helpers(m_index, m_names, m_freeFunctionsByName, m_ownedNodes),
      m_constructions(m_index, m_names, m_helpers),
      m_parameters(files, m_index, m_names, m_helpers),
      m_nodeNames(m_index, m_names, m_constructions),
      m_entryPoints(m_index, m_freeFunctionsByName, m_constructions,
                    [this](int cls) { return m_nodeNames.of(cls); })
{
    for (const CppFileFacts &file : files) {
        for (auto it = file.aliases.constBegin(); it != file.aliases.constEnd(); ++it) {
            if (!canonicalInterfaceType(it.value()).contains(u'/'))
                continue;
            for (const QString &scope : {file.package, QString()}) {
                QHash<QString, QString> &aliases = m_interfaceAliases[scope];
                if (!aliases.contains(it.key()))
                    aliases.insert(it.key(), it.value());
            }
        }
    }
    // What each class's members hold and which parameters it declares, in source order.
    m_facts.resize(size_t(m_index.size()));
    for (int i = 0; i < m_index.size(); ++i) {
        CppMemberFacts &f = m_facts[size_t(i)];
        const CppClassIndex::ClassInfo &info = m_index.at(i);
        for (const CppMemberBinding &b : info.cls->memberInitializers)
            f.bindings[b.member].append({b.value, nullptr, info.file});
        for (const auto &ref : info.functions) {
            for (const CppMemberBinding &b : ref.function->memberBindings)
                f.bindings[b.member].append({b.value, ref.function, ref.file});
            for (const CppParameterDeclaration &d : ref.function->parameterDeclarations)
                if (!d.parameter.isEmpty() && !f.parameters.contains(d.parameter))
                    f.parameters.insert(d.parameter, d);
        }
    }
    for (const auto &ref : m_index.freeFunctions())
        if (ref.function->name != QLatin1String("main"))
            m_freeFunctionsByName[ref.function->name].append(ref);
    m_ownedNodes.assign(size_t(m_index.size()), nullptr);
    QSet<QString> registered;
    for (const CppFileFacts &file : files)
        for (const ComponentRegistration &r : file.registrations)
            registered.insert(r.pluginClass.startsWith(QLatin1String("::")) ? r.pluginClass.mid(2)
                                                                            : r.pluginClass);
    for (int i = 0; i < m_index.size(); ++i) {
        const CppClassIndex::ClassInfo &info = m_index.at(i);
        if (info.node)
            continue;
        // gtest fixtures own throwaway nodes; they are test scaffolding, not components.
        bool fixture = false;
        for (const QString &base : info.cls->bases)
            fixture = fixture || base.contains(QLatin1String("testing::Test"));
        if (fixture)
            continue;
        const CppProceduralNode *owned = nullptr;
        bool ports = false;
        for (const auto &ref : info.functions) {
            ports = ports || !ref.function->ports.isEmpty();
            for (const CppProceduralNode &pn : ref.function->proceduralNodes)
                if (pn.member && !owned)
                    owned = &pn;
        }
        if (owned && (ports || registered.contains(info.cls->qualifiedName)))
            m_ownedNodes[size_t(i)] = owned;
    }
}

const CppProceduralNode *CppNodeLinker::ownedNode(int cls) const
{
    return cls >= 0 && cls < int(m_ownedNodes.size()) ? m_ownedNodes[size_t(cls)] : nullptr;
}

LanguageAnalysis CppNodeLinker::link() const
{
    LanguageAnalysis out;
    // Where a helper chain went deeper than followed, one note per node.
    const auto reportBounds = [&](const AtomicNode &node, const QList<Evidence> &hit) {
        if (hit.isEmpty())
            return;
        Diagnostic d;
        d.severity = Diagnostic::Severity::Info;
        d.code = QStringLiteral("helper-depth");
        d.message =
            QStringLiteral("Stopped following the helpers of %1 here (bound: %2 levels "
                           "of helpers); ports created and parameters declared beyond it are "
                           "not given to it.")
                .arg(node.className)
                .arg(CppHelperPorts::kMaxHelperDepth);
        d.evidence = hit.front();
        out.diagnostics.append(d);
    };
    // The classes each on their own, in parallel (autoware: ~40 ms of one core), in order.
    struct Linked
    {
        std::optional<AtomicNode> node;
        QList<Evidence> boundsHit;
    };
    std::vector<int> classes(size_t(m_index.size()));
    std::iota(classes.begin(), classes.end(), 0);
    const std::function<Linked(int)> linkClass = [this](int i) {
        Linked linked;
        if (m_index.at(i).node)
            linked.node = classNode(i);
        else if (const CppProceduralNode *owned = ownedNode(i))
            linked.node = classNode(i, owned);
        linked.boundsHit = m_helpers.takeBoundsHit();
        return linked;
    };
    for (const Linked &linked :
         QtConcurrent::blockingMapped<std::vector<Linked>>(classes, linkClass)) {
        if (!linked.node)
            continue;
        out.nodes.append(*linked.node);
        reportBounds(out.nodes.last(), linked.boundsHit);
    }
    QHash<QString, int> stems;
    for (const auto &ref : m_index.freeFunctions()) {
        if (isMacroFunction(ref.function->name))
            continue;
        QList<AtomicNode> procedural;
        addProceduralNodes(ref, &procedural, &stems);
        const QList<Evidence> hit = m_helpers.takeBoundsHit();
        if (!procedural.isEmpty())
            reportBounds(procedural.first(), hit);
        QList<Evidence> builderBoundsHit;
        addEntryPoint(ref, procedural, &out.entryPoints, &builderBoundsHit);
        out.nodes += procedural;
        if (!builderBoundsHit.isEmpty()) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Info;
            d.code = QStringLiteral("builder-depth");
            d.message = QStringLiteral("Stopped following the functions main() calls here "
                                       "(bound: %1 calls deep); nodes built beyond it are not "
                                       "instances of the executable.")
                            .arg(CppEntryPoints::kMaxBuilderDepth);
            d.evidence = builderBoundsHit.front();
            out.diagnostics.append(d);
        }
    }
    QSet<int> plugins;
    for (const CppFileFacts &file : m_files) {
        for (const CppPluginExport &e : file.pluginExports) {
            const QString written =
                e.className.startsWith(QLatin1String("::")) ? e.className.mid(2) : e.className;
            QHash<QString, QString> templateArguments;
            const int c = pluginClass(written, file, &templateArguments);
            if (c < 0 || m_index.at(c).node || ownedNode(c) || plugins.contains(c))
                continue;
            plugins.insert(c);
            // A plugin that creates no ports and declares no parameters (a planner's math) is
            // no part of the architecture.
            AtomicNode n = pluginNode(c, e, templateArguments);
            const QList<Evidence> hit = m_helpers.takeBoundsHit();
            if (!n.ports.isEmpty() || !n.parameters.isEmpty()) {
                out.nodes.append(n);
                reportBounds(n, hit);
            }
        }
    }
    for (const CppFileFacts &file : m_files)
        out.registrations += file.registrations;
    std::stable_sort(out.nodes.begin(), out.nodes.end(),
                     [](const AtomicNode &a, const AtomicNode &b) {
                         if (a.packageName != b.packageName)
                             return a.packageName < b.packageName;
                         if (a.className != b.className)
                             return a.className < b.className;
                         if (a.qualifiedName != b.qualifiedName)
                             return a.qualifiedName < b.qualifiedName;
                         return evidenceLess(a.evidence, b.evidence);
                     });
    out.helperParameters = m_parameters.helperDeclarations();
    return out;
}

AtomicNode CppNodeLinker::classNode(int index, const CppProceduralNode *owned) const
{
    const CppClassIndex::ClassInfo &info = m_index.at(index);
    AtomicNode node;
    node.className = info.cls->name;
    node.qualifiedName = info.cls->qualifiedName;
    node.packageName = info.file->package;
    node.compileType = AtomicNode::CompileType::Cpp;
    node.baseClasses = info.cls->bases;
    node.lifecycle = info.lifecycle;
    node.evidence = info.cls->evidence;
    QStringList files{info.file->path};
    for (const auto &ref : info.functions)
        if (!files.contains(ref.file->path))
            files.append(ref.file->path);
    for (const QString &f : std::as_const(files))
        (isHeaderPath(f) ? node.headerFiles : node.sourceFiles).append(f);
    node.headerFiles.sort();
    node.sourceFiles.sort();

    node.nodeName = m_nodeNames.of(index);
    if (owned) { // a component that owns its rclcpp::Node instead of deriving from it
        node.nodeName =
            owned->nodeName.kind == CppValue::Kind::Literal
                ? owned->nodeName.literal
                : m_nodeNames.literalName(owned->nodeName, {index, nullptr, nullptr, nullptr});
        node.lifecycle = owned->lifecycle;
    }

    QList<Port> ports = portsOf(index, false);
    const QList<int> lineage = m_index.lineage(index);
    for (qsizetype i = 1; i < lineage.size(); ++i) {
        // `class PathToTrajectory : public ConverterBase<Path, Trajectory>`: the base's ports
        // typed by its template parameters take the types the derived class gives them.
        QHash<QString, QString> typed;
        QStringList templateArguments;
        const QStringList &parameters = m_index.at(lineage[i]).cls->templateParameters;
        for (qsizetype d = 0; d < i && !parameters.isEmpty() && typed.isEmpty(); ++d) {
            const CppClassIndex::ClassInfo &derived = m_index.at(lineage[d]);
            for (const QString &base : derived.cls->bases) {
                const QString plain = withoutTemplateArguments(base).remove(u' ');
                if (m_index.lookup(plain, derived.cls->scope, derived.file) != lineage[i])
                    continue;
                templateArguments = templateArgumentsOf(base.simplified());
                for (qsizetype a = 0; a < parameters.size() && a < templateArguments.size(); ++a)
                    typed.insert(parameters.at(a), templateArguments.at(a));
            }
        }
        QList<Port> inherited = portsOf(lineage[i], true, typed);
        // `AssistedTeleopServer() : TestActionServer("assisted_teleop")`: the base's ports
        // named by its constructor's parameters, as the derived class's constructor fills them.
        CppLinkContext at;
        const bool open = std::any_of(inherited.cbegin(), inherited.cend(),
                                      [](const Port &p) { return !p.isResolved(); });
        if (const CppBaseInitializer *init =
                open ? m_nodeNames.baseInitializer(lineage, i, &at) : nullptr) {
            // (the bounds this pass hits are the class's own pass's, reported there)
            const QList<Evidence> hit = m_helpers.takeBoundsHit();
            const QList<Port> filled =
                m_helpers.constructedPorts(lineage[i], init->arguments, at, templateArguments);
            m_helpers.takeBoundsHit();
            for (const Evidence &e : hit)
                m_helpers.boundHit(e);
            const auto sameCall = [](const Port &a, const Port &b) {
                return a.kind == b.kind && a.evidence == b.evidence;
            };
            for (Port &p : inherited) {
                // one port per call on both sides (a lazy helper makes several at one call)
                const auto same = std::find_if(filled.cbegin(), filled.cend(),
                                               [&](const Port &c) { return sameCall(c, p); });
                const auto calls = [&](const QList<Port> &list) {
                    return std::count_if(list.cbegin(), list.cend(),
                                         [&](const Port &c) { return sameCall(c, p); });
                };
                if (same != filled.cend() && !p.isResolved() && same->isResolved() &&
                    calls(filled) == 1 && calls(inherited) == 1) {
                    p.name = same->name;
                    p.nameOrigin = same->nameOrigin;
                    p.nameExpression = same->nameExpression;
                    p.parameter = same->parameter;
                    p.parameterPrefix = same->parameterPrefix;
                    p.parameterSuffix = same->parameterSuffix;
                }
            }
        }
        ports += inherited;
    }
    std::stable_sort(ports.begin(), ports.end(), [](const Port &a, const Port &b) {
        return evidenceLess(a.evidence, b.evidence);
    });
    // One call can be reached twice (a helper instantiated twice with the same arguments).
    appendUnique(&node.ports, ports);
    node.children = childNodesOf(index);
    node.parameters = m_parameters.declarations(index);
    node.acceptsUndeclared = m_parameters.acceptsUndeclared(index);
    return node;
}

// The nodes a node class (or one of its project bases) constructs in its own code:
// `costmap_ros_ = std::make_shared<nav2_costmap_2d::Costmap2DROS>("global_costmap", ...)`.
QList<ChildNode> CppNodeLinker::childNodesOf(int index) const
{
    const QList<int> lineage = m_index.lineage(index);
    QList<ChildNode> out;
    for (int c : lineage) {
        for (const auto &ref : m_index.at(c).functions) {
            const CppLinkContext ctx{c, ref.function, ref.file, nullptr};
            for (const CppInstantiation &inst : ref.function->instantiations) {
                if (inst.className.isEmpty() || !inst.member.isEmpty())
                    continue;
                const int t = m_index.lookup(withoutTemplateArguments(inst.className).remove(u' '),
                                             m_names.scopeOf(ctx), ref.file);
                if (t < 0 || !m_index.at(t).node || lineage.contains(t))
                    continue;
                const ChildNode child = m_constructions.child(t, inst, ctx, m_nodeNames.of(t));
                if (!out.contains(child))
                    out.append(child);
            }
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const ChildNode &a, const ChildNode &b) {
        return evidenceLess(a.evidence, b.evidence);
    });
    return out;
}

// The exported class, also when it is an alias of a template instance
// (`using SmacPlannerHybrid = SmacPlannerHybridT<NodeHybrid>;` in a header of the package).
int CppNodeLinker::pluginClass(const QString &written, const CppFileFacts &file,
                               QHash<QString, QString> *templateArguments) const
{
    const int c = m_index.lookup(written, {}, &file);
    if (c >= 0)
        return c;
    QStringList scope = splitScope(written);
    const QString name = scope.isEmpty() ? QString() : scope.takeLast();
    for (const CppFileFacts &f : m_files) {
        const QString target = f.package == file.package ? f.aliases.value(name) : QString();
        if (target.isEmpty())
            continue;
        const int t = m_index.lookup(withoutTemplateArguments(target).remove(u' '), scope, &f);
        if (t < 0)
            continue;
        const QStringList arguments = templateArgumentsOf(target.simplified());
        const QStringList &parameters = m_index.at(t).cls->templateParameters;
        for (qsizetype i = 0; i < parameters.size() && i < arguments.size(); ++i)
            templateArguments->insert(parameters.at(i), arguments.at(i));
        return t;
    }
    return -1;
}

AtomicNode CppNodeLinker::pluginNode(int index, const CppPluginExport &exported,
                                     const QHash<QString, QString> &templateArguments) const
{
    AtomicNode node = classNode(index);
    node.nodeName.clear();
    // Named as exported, which is how parameter files name it (an alias of a template instance
    // included: nav2_smac_planner::SmacPlannerHybrid for SmacPlannerHybridT<NodeHybrid>).
    node.qualifiedName = exported.className.startsWith(QLatin1String("::"))
                             ? exported.className.mid(2)
                             : exported.className;
    node.className = lastSegment(node.qualifiedName);
    node.pluginInterface = exported.baseClass.startsWith(QLatin1String("::"))
                               ? exported.baseClass.mid(2)
                               : exported.baseClass;
    node.ports.clear();
    const std::map<int, CppSubstitution> substitutions =
        pluginSubstitutions(index, templateArguments);
    QList<Port> ports = pluginPorts(index, substitutions);
    node.parameters = m_parameters.declarations(index, &substitutions);
    std::stable_sort(ports.begin(), ports.end(), [](const Port &a, const Port &b) {
        return evidenceLess(a.evidence, b.evidence);
    });
    appendUnique(&node.ports, ports);
    return node;
}

// Every class on the plugin's lineage creates ports through the node handle its entry points
// are given (`configure(parent, ...)`, `initialize(node)`, a `weak_ptr` locked); a template
// base (BehaviorTreeNavigator<ActionT>) sees the arguments the plugin gives it, and a virtual
// `getName()` is the plugin's.
std::map<int, CppSubstitution>
CppNodeLinker::pluginSubstitutions(int plugin,
                                   const QHash<QString, QString> &templateArguments) const
{
    static const CppFunction noCall; // no parameter stands for an argument
    const QList<int> lineage = m_index.lineage(plugin);
    std::map<int, CppSubstitution> substitutions; // stable references while inserting
    substitutions.emplace(plugin, CppSubstitution{{}, {}, templateArguments, &noCall, true});
    for (int c : lineage) {
        const CppClassIndex::ClassInfo &info = m_index.at(c);
        const CppSubstitution &own = substitutions[c];
        const CppLinkContext here{c, nullptr, info.file, &own, plugin};
        for (const QString &base : info.cls->bases) {
            const int b = m_index.lookup(withoutTemplateArguments(base).remove(u' '),
                                         m_names.scopeOf(here), info.file);
            if (b < 0 || substitutions.count(b))
                continue;
            CppSubstitution subst{{}, {}, {}, &noCall, true};
            const QStringList arguments = templateArgumentsOf(base.simplified());
            const QStringList &parameters = m_index.at(b).cls->templateParameters;
            for (qsizetype i = 0; i < parameters.size() && i < arguments.size(); ++i)
                subst.templateArguments.insert(parameters.at(i),
                                               m_names.expandAliases(arguments.at(i), here));
            substitutions.emplace(b, subst);
        }
    }
    return substitutions;
}

QList<Port> CppNodeLinker::pluginPorts(int plugin,
                                       const std::map<int, CppSubstitution> &substitutions) const
{
    QList<Port> ports;
    for (int c : m_index.lineage(plugin)) {
        const auto found = substitutions.find(c);
        if (found == substitutions.end())
            continue;
        const CppSubstitution &subst = found->second;
        for (const auto &ref : m_index.at(c).functions) {
            const CppLinkContext ctx{c, ref.function, ref.file, &subst, plugin};
            for (const CppPortCall &call : ref.function->ports) {
                if (call.typeIsTemplateParameter &&
                    !subst.templateArguments.contains(splitScope(call.typeWritten).value(0)))
                    continue;
                Port p = m_names.port(call, ctx);
                p.inherited = c != plugin;
                ports.append(p);
            }
            m_helpers.addCallPorts(*ref.function, ctx, 0, &ports);
        }
        m_helpers.addMemberHelperPorts(c, plugin, &ports);
    }
    return ports;
}

QList<Port> CppNodeLinker::portsOf(int cls, bool inherited,
                                   const QHash<QString, QString> &templateArguments) const
{
    QList<Port> ports;
    // A port typed by a template parameter of the node class itself is one, its type decided
    // where the class is built (`PassStage<sensor_msgs::msg::LaserScan>`); other generic code
    // (a function template's own parameter) makes none.
    const QStringList &own = m_index.at(cls).cls->templateParameters;
    for (const auto &ref : m_index.at(cls).functions) {
        const CppLinkContext ctx{cls, ref.function, ref.file, nullptr};
        for (const CppPortCall &call : ref.function->ports) {
            if (!call.typeIsTemplateParameter) {
                ports.append(m_names.port(call, ctx));
                continue;
            }
            const QString head = splitScope(withoutTemplateArguments(call.typeWritten)).value(0);
            if (!ref.function->templateParameters.isEmpty() || !own.contains(head))
                continue;
            if (templateArguments.contains(head)) { // as a derived class instantiates it
                Port p = m_names.port(call, ctx);
                p.type = m_names.resolveType(templateArguments.value(head), ctx);
                ports.append(p);
            } else if (!inherited) { // the class template itself: typed where it is built
                ports.append(m_names.port(call, ctx));
            }
        }
        m_helpers.addMessageFilterPorts(cls, ref, &ports);
        m_helpers.addCallPorts(*ref.function, ctx, 0, &ports);
    }
    m_helpers.addMemberHelperPorts(cls, -1, &ports);
    for (Port &p : ports)
        p.inherited = inherited;
    return ports;
}

void CppNodeLinker::addProceduralNodes(const CppClassIndex::FunctionRef &ref,
                                       QList<AtomicNode> *nodes, QHash<QString, int> *stems) const
{
    const CppFunction &fn = *ref.function;
    const CppLinkContext ctx{-1, &fn, ref.file, nullptr};
    QStringList variables;
    for (const CppProceduralNode &pn : fn.proceduralNodes) {
        // `node = make_shared<rclcpp::Node>(...)` in both branches of an if: one node.
        if (!pn.variable.isEmpty() && variables.contains(pn.variable))
            continue;
        variables.append(pn.variable);
        AtomicNode node;
        const QString stem = fileStem(ref.file->path);
        const int seen = (*stems)[ref.file->path]++;
        node.className = seen == 0 ? stem : QStringLiteral("%1_%2").arg(stem).arg(seen + 1);
        node.qualifiedName = node.className;
        node.packageName = ref.file->package;
        node.compileType = AtomicNode::CompileType::Cpp;
        node.procedural = true;
        node.lifecycle = pn.lifecycle;
        node.evidence = fn.evidence;
        (isHeaderPath(ref.file->path) ? node.headerFiles : node.sourceFiles).append(ref.file->path);
        node.nodeName = m_nodeNames.literalName(pn.nodeName, ctx);
        if (pn.variable.isEmpty()) {
            nodes->append(node);
            continue;
        }
        auto onVariable = [&](const QString &receiver) {
            if (receiver == pn.variable)
                return true;
            if (!receiver.startsWith(pn.variable))
                return false;
            const QChar next = receiver.at(pn.variable.size());
            return !next.isLetterOrNumber() && next != u'_';
        };
        for (const CppPortCall &call : fn.ports)
            if (!call.typeIsTemplateParameter && onVariable(call.receiver))
                node.ports.append(m_names.port(call, ctx));
        // Helpers handed this node see it as `this` would be seen in a node class.
        auto handOver = [&](QList<CppValue> *arguments) {
            bool uses = false;
            for (CppValue &arg : *arguments) {
                if (arg.text == pn.variable || arg.text == QStringLiteral("*") + pn.variable) {
                    arg.kind = CppValue::Kind::SelfNode;
                    uses = true;
                }
            }
            return uses;
        };
        for (CppInstantiation inst : fn.instantiations)
            if (handOver(&inst.arguments))
                m_helpers.addHelperPorts(inst, ctx, 0, &node.ports);
        for (CppFreeCall call : fn.freeCalls)
            if (handOver(&call.arguments))
                m_helpers.addFreeCallPorts(call, ctx, 0, &node.ports);
        std::stable_sort(node.ports.begin(), node.ports.end(), [](const Port &a, const Port &b) {
            return evidenceLess(a.evidence, b.evidence);
        });
        nodes->append(node);
    }
}

void CppNodeLinker::addEntryPoint(const CppClassIndex::FunctionRef &ref,
                                  const QList<AtomicNode> &procedural,
                                  QList<EntryPoint> *entryPoints,
                                  QList<Evidence> *builderBoundsHit) const
{
    const CppFunction &fn = *ref.function;
    EntryPoint entry;
    entry.file = ref.file->path;
    entry.function = fn.name;
    entry.evidence = fn.evidence;
    m_entryPoints.addConstructions(ref, &entry, builderBoundsHit);
    for (const AtomicNode &node : procedural)
        if (!entry.instantiatedClasses.contains(node.className))
            entry.instantiatedClasses.append(node.className);
    if (!entry.instantiatedClasses.isEmpty())
        entryPoints->append(entry);
}

} // namespace rosarch
