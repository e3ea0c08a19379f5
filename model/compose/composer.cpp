#include "compose/composer.h"
#include "compose/itemports.h"
#include "core/rosnames.h"

#include <QHash>
#include <QSet>

#include <algorithm>

namespace rosarch {

namespace {

enum class Family
{
    Topic,
    Service,
    Action
};

Family familyOf(PortKind k)
{
    switch (k) {
    case PortKind::Publisher:
    case PortKind::Subscriber:
        return Family::Topic;
    case PortKind::ServiceServer:
    case PortKind::ServiceClient:
        return Family::Service;
    default:
        return Family::Action;
    }
}

QString runtimeNodeName(const AtomicNode &node, const NodeInstance &instance)
{
    if (!instance.nodeName.isEmpty())
        return instance.nodeName;
    if (!node.nodeName.isEmpty())
        return node.nodeName;
    return instance.execName;
}

/// A PlantUML-safe alias from a name: "/robot_ns/scan" -> "robot_ns_scan".
QString aliasOf(const QString &prefix, const QString &name, QSet<QString> *taken)
{
    QString s;
    for (const QChar c : name)
        s += c.isLetterOrNumber() && c.unicode() < 128 ? c : QLatin1Char('_');
    while (s.startsWith(QLatin1Char('_')))
        s.remove(0, 1);
    while (s.contains(QLatin1String("__")))
        s.replace(QLatin1String("__"), QLatin1String("_"));
    QString alias = prefix + (s.isEmpty() ? QStringLiteral("root") : s);
    const QString base = alias;
    for (int n = 2; taken->contains(alias); ++n)
        alias = QStringLiteral("%1_%2").arg(base).arg(n);
    taken->insert(alias);
    return alias;
}

struct Endpoint
{
    const RosNodePart *part;
    const PartPort *port;
};

/// Binds ports with a counterpart into channels and promotes the rest to the boundary.
void wire(Composite *c)
{
    struct Group
    {
        Family family;
        QString name;
        bool guessed;
    };
    QList<Group> order;
    QHash<QString, QList<Endpoint>> groups;
    // A name built on a guess meets only names built on a guess: under another value of the
    // launch argument, it would not be the decided name it happens to equal under the guess.
    // A launch file's own CCD lives in the root namespace (blueprint §1, "Wiring in a launch
    // file's own CCD"): its relative `a/b` and an absolute `/a/b` are one channel; the names
    // keep their spelling, the first one met names the channel.
    auto keyOf = [](Family f, const QString &name, bool guessed) {
        return QString::number(int(f)) + (guessed ? u'?' : u':') +
               (name.startsWith(QLatin1Char('/')) ? name : QLatin1Char('/') + name);
    };
    for (const RosNodePart &part : c->parts) {
        if (!part.active)
            continue;
        for (const PartPort &port : part.ports) {
            if (!port.active || !port.resolved)
                continue;
            const Family f = familyOf(port.kind);
            const QString key = keyOf(f, port.name, port.guessed);
            if (!groups.contains(key))
                order.append({f, port.name, port.guessed});
            groups[key].append({&part, &port});
        }
    }
    QSet<QString> aliases;
    QHash<QString, int> counters;
    for (const auto &[family, name, guessed] : order) {
        const QList<Endpoint> &eps = groups.value(keyOf(family, name, guessed));
        const bool providers = std::any_of(eps.begin(), eps.end(), [](const Endpoint &e) {
            return isProvidingPort(e.port->kind);
        });
        const bool users = std::any_of(eps.begin(), eps.end(), [](const Endpoint &e) {
            return !isProvidingPort(e.port->kind);
        });
        if (providers && users) {
            Channel ch;
            ch.kind = family == Family::Topic     ? Channel::Kind::Topic
                      : family == Family::Service ? Channel::Kind::Service
                                                  : Channel::Kind::Action;
            const QString prefix = family == Family::Topic     ? QStringLiteral("q_")
                                   : family == Family::Service ? QStringLiteral("c_")
                                                               : QStringLiteral("a_");
            ch.id = aliasOf(prefix, name, &aliases);
            ch.name = name;
            for (const Endpoint &e : eps) {
                if (ch.type.isEmpty())
                    ch.type = e.port->type;
                // a channel a correction renamed, or joined, is a corrected one
                ch.marks.provenance = std::max(ch.marks.provenance, e.port->marks.provenance);
            }
            c->channels.append(ch);
            for (bool provider : {true, false}) {
                for (const Endpoint &e : eps) {
                    if (isProvidingPort(e.port->kind) != provider)
                        continue;
                    Connection::Kind k =
                        family == Family::Topic
                            ? (provider ? Connection::Kind::Publish : Connection::Kind::Subscribe)
                            : (provider ? Connection::Kind::Server : Connection::Kind::Client);
                    c->connections.append({k, e.part->id, e.port->id, ch.id});
                }
            }
            continue;
        }
        // Delegation is one to one (blueprint §1): each promoted inner port gets its own
        // boundary port, even when two share a topic; the name travels with each of them.
        for (const Endpoint &e : eps) {
            const QString prefix = portIdPrefix(e.port->kind);
            const QString id = prefix + QString::number(++counters[prefix]);
            c->boundary.append({id, e.port->kind, e.port->name, e.port->type, e.port->guessed});
            const bool in = c->boundary.constLast().isInput();
            c->connections.append(
                {in ? Connection::Kind::DelegationIn : Connection::Kind::DelegationOut, e.part->id,
                 e.port->id, id});
        }
    }
}

QString namespaceOfInclude(const LaunchFileInstance &parent, const QString &childId)
{
    for (auto it = parent.namespaces.cbegin(); it != parent.namespaces.cend(); ++it)
        if (it.value().contains(childId))
            return it.key();
    return QStringLiteral("/");
}

bool evidenceBefore(const Evidence &a, const Evidence &b)
{
    return std::tie(a.line, a.column) < std::tie(b.line, b.column);
}

} // namespace

QString channelKey(PortKind kind, const QString &name)
{
    return portFamilyName(kind) + QLatin1Char(':') + name;
}

QString launchStem(const QString &fileName)
{
    QString stem = fileName.section(QLatin1Char('/'), -1);
    for (const char *suffix :
         {".launch.py", ".launch.xml", ".launch.yaml", ".launch.yml", "_launch.py", "_launch.xml",
          "_launch.yaml", ".py", ".xml", ".yaml", ".yml", ".launch"}) {
        if (stem.endsWith(QLatin1String(suffix)) && stem.size() > int(qstrlen(suffix))) {
            stem.chop(int(qstrlen(suffix)));
            break;
        }
    }
    return stem;
}

QList<PartPort> Composer::resolvePorts(const AtomicNode &node, const NodeInstance &instance,
                                       const NodeInstance *container, QList<int> *rulesUsed)
{
    QList<QPair<QString, QString>> rules = instance.remaps;
    if (container && container != &instance)
        rules += container->remaps; // process-wide rules of the container reach its components
    const QString nodeName = runtimeNodeName(node, instance);
    QList<PartPort> out;
    QList<Port> ports;
    for (const Port &p : node.ports) {
        if (instance.removedPorts.contains(p.id))
            continue;
        // A node built in an executable's code: the port as its constructor's arguments name it.
        const auto constructed =
            std::find_if(instance.constructedPorts.cbegin(), instance.constructedPorts.cend(),
                         [&](const Port &c) { return c.id == p.id; });
        const Port &own = constructed != instance.constructedPorts.cend() ? *constructed : p;
        if (itemList(own).isEmpty())
            ports.append(own);
        else
            expandItems(own, instance, &ports);
    }
    ports += instance.addedPorts;
    const qsizetype firstModelled = ports.size();
    ports += instance.modelledPorts;
    for (const Port &p : std::as_const(ports)) {
        PartPort pp;
        pp.id = p.id;
        pp.kind = p.kind;
        pp.nameAsWritten = p.name;
        pp.type = p.type;
        pp.guard = p.guard;
        pp.qos = p.qos;
        pp.evidence = p.evidence;
        pp.marks = p.marks;
        if (&p - ports.constData() >= firstModelled)
            pp.model = instance.interfaceModel;
        pp.resolved = p.isResolved();
        QString base = p.name;
        // `get_name() + "/map"`: the instance's own node name (a guess when that is one)
        const bool namedByNode = base.contains(QLatin1String(kNodeNamePlaceholder));
        if (namedByNode && !nodeName.isEmpty())
            base.replace(QLatin1String(kNodeNamePlaceholder), nodeName);
        else if (namedByNode)
            pp.resolved = false;
        if (!itemList(p).isEmpty() || !loadedPluginClass(p).isEmpty()) // not given by it
            pp.resolved = false;
        if (p.nameOrigin == NameOrigin::Parameter) {
            pp.parameterDerived = true;
            bool set = false;
            const QString v = settingValue(instance, p.parameter, &set);
            if (set && !v.isEmpty()) // a joined name keeps the text around the value
                base = p.parameterPrefix + v + p.parameterSuffix;
        }
        // A parameter left empty (declared with "" and not set) names nothing ROS would
        // accept: the name is only known at run time.
        if (pp.resolved && base.trimmed().isEmpty()) {
            pp.resolved = false;
            base = !p.nameExpression.isEmpty() ? p.nameExpression
                   : !p.parameter.isEmpty()    ? QStringLiteral("$(%1)").arg(p.parameter)
                                               : QStringLiteral("?");
        }
        if (pp.resolved) {
            base = RosNames::withParentNamespace(base, instance.nameSpace);
            // `get_namespace() + "/scan"`: the instance's namespace, which it always has
            base = RosNames::withNamespace(base, instance.nameSpace);
            int used = -1;
            pp.name = RosNames::remap(base, rules, instance.nameSpace, nodeName, &used);
            pp.remapped = used >= 0;
            pp.remap = used;
            // A rule past the instance's own is the container's (process-wide).
            pp.guessed = used >= 0 && (used < instance.remaps.size()
                                           ? instance.guessedRemaps.contains(used)
                                           : container && container->guessedRemaps.contains(
                                                              used - int(instance.remaps.size())));
            // A relative name takes the namespace, a private one the node's name too: when
            // those rest on a guess, so does the name.
            const QString written = (used >= 0 ? rules.at(used).second : base).trimmed();
            if (!written.startsWith(QLatin1Char('/')) &&
                (instance.guessedNamespace ||
                 (written.startsWith(QLatin1Char('~')) && instance.guessedName)))
                pp.guessed = true;
            if (namedByNode && instance.guessedName)
                pp.guessed = true;
            if (used >= 0 && rulesUsed)
                rulesUsed->append(used);
        } else {
            pp.name = base;
        }
        pp.name = RosNames::scopeRelative(pp.name); // a classifier's relative names stay relative
        if (!p.guard.isEmpty() && !p.guardParameter.isEmpty()) {
            bool set = false;
            QString v = settingValue(instance, p.guardParameter, &set);
            if (!set)
                v = p.guardDefault;
            bool known = false;
            const bool holds = RosNames::evaluateGuard(p.guard, v, &known);
            pp.active = !known || holds;
        }
        out.append(pp);
    }
    return out;
}

bool Composer::guardDecided(const Port &p, const NodeInstance &instance)
{
    if (p.guard.isEmpty())
        return true;
    if (p.guardParameter.isEmpty())
        return false;
    bool set = false;
    QString v = settingValue(instance, p.guardParameter, &set);
    if (!set)
        v = p.guardDefault;
    bool known = false;
    RosNames::evaluateGuard(p.guard, v, &known);
    return known;
}

// A node instance carries the ports of the pluginlib plugins its parameters load
// (`FollowPath.plugin: dwb_core::DWBLocalPlanner`), each port id prefixed by the plugin's name.
QList<PartPort> Composer::pluginPorts(const QHash<QString, const AtomicNode *> &pluginClasses,
                                      const NodeInstance &instance, const NodeInstance *container)
{
    QList<PartPort> out;
    // The plugin's own ports only: what corrections and interface models add to the instance,
    // and the ports its constructors name, belong to the node, once (ids would also collide).
    NodeInstance host = instance;
    host.addedPorts.clear();
    host.modelledPorts.clear();
    host.constructedPorts.clear();
    host.removedPorts.clear();
    for (const ParameterSetting &plugin : instance.plugins) {
        const AtomicNode *cls = pluginClass(plugin.value, pluginClasses);
        if (!cls)
            continue;
        AtomicNode loaded = *cls; // the plugin under the name it is loaded by
        for (Port &p : loaded.ports) {
            p.name.replace(QLatin1String(kPluginNamePlaceholder), plugin.name);
            p.parameter.replace(QLatin1String(kPluginNamePlaceholder), plugin.name);
        }
        for (PartPort pp : resolvePorts(loaded, host, container)) {
            pp.id = QStringLiteral("%1_%2").arg(plugin.name, pp.id);
            if (!instance.removedPorts.contains(pp.id))
                out.append(pp);
        }
    }
    return out;
}

Architecture Composer::run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                           const StageControl &control, const QHash<QString, QString> &renamed)
{
    Architecture arch;
    QHash<QString, const AtomicNode *> classes;
    QHash<QString, const AtomicNode *> pluginClasses; // by qualified name
    for (const AtomicNode &n : nodes.nodes) {
        classes.insert(n.id, &n);
        if (n.isPlugin())
            pluginClasses.insert(n.qualifiedName, &n);
    }
    QHash<QString, const NodeInstance *> instances;
    QHash<QString, const NodeInstance *> byName; // containers referred to by name
    for (const NodeInstance &n : launch.nodes) {
        instances.insert(n.id, &n);
        byName.insert(RosNames::fullyQualified(n.nameSpace, n.nodeName), &n);
        byName.insert(n.nodeName, &n);
    }
    // Component containers are deployment, not architecture (blueprint §1): the process that
    // hosts composable nodes is not a part; its components are, each recording its container.
    QSet<QString> containers;
    for (const NodeInstance &n : launch.nodes) {
        if (n.execName.startsWith(QLatin1String("component_container")))
            containers.insert(n.id);
        if (!n.container.isEmpty())
            if (const NodeInstance *host = instances.value(n.container, byName.value(n.container)))
                containers.insert(host->id);
    }

    QHash<QString, const LaunchFileInstance *> launchInstances;
    for (const LaunchFileInstance &lf : launch.instances)
        if (!launchInstances.contains(lf.id)) // the first, as LaunchDependencies::instance()
            launchInstances.insert(lf.id, &lf);
    QHash<QString, Composite> built;
    const int total = int(launch.instances.size());
    for (int i = total - 1; i >= 0; --i) { // children come after their parent: build them first
        if (control.isCanceled()) {
            arch.canceled = true;
            return arch;
        }
        const LaunchFileInstance &lf = launch.instances.at(i);
        Composite c;
        c.instanceId = lf.id;
        c.stem = launchStem(lf.type);
        c.file = lf.file;
        c.package = lf.package;
        c.parentId = lf.parentId;
        if (lf.format == QLatin1String("executable"))
            c.executable = lf.type;

        struct Entry
        {
            bool node;
            QString id;
            Evidence evidence;
        };
        QList<Entry> entries;
        for (const QString &id : lf.nodes)
            if (const NodeInstance *n = instances.value(id); n && !containers.contains(id))
                entries.append({true, id, n->evidence});
        for (const QString &id : lf.includedLaunchFiles)
            if (const LaunchFileInstance *child = launchInstances.value(id))
                entries.append({false, id, child->evidence});
        std::stable_sort(entries.begin(), entries.end(), [&](const Entry &a, const Entry &b) {
            const bool aHere = a.evidence.file == lf.file, bHere = b.evidence.file == lf.file;
            if (aHere != bHere)
                return aHere;
            return evidenceBefore(a.evidence, b.evidence);
        });

        for (const Entry &e : entries) {
            RosNodePart part;
            part.id = QStringLiteral("part%1").arg(c.parts.size() + 1);
            part.instanceId = e.id;
            part.evidence = e.evidence;
            if (e.node) {
                const NodeInstance &n = *instances.value(e.id);
                const AtomicNode *cls = classes.value(n.classId);
                part.kind = RosNodePart::Kind::Node;
                // a node of a package outside the workspace is typed `package/executable`
                part.typeName = !n.className.isEmpty() ? n.className
                                : n.package.isEmpty() || n.execName.isEmpty()
                                    ? n.execName
                                    : QStringLiteral("%1/%2").arg(n.package, n.execName);
                part.typeId = n.classId;
                part.nameSpace = n.nameSpace.isEmpty() ? QStringLiteral("/")
                                                       : RosNames::scopeRelative(n.nameSpace);
                part.active = n.active && lf.active;
                part.typed = cls != nullptr;
                part.marks = n.marks;
                if (!cls && (!n.addedPorts.isEmpty() || !n.modelledPorts.isEmpty())) {
                    // an unknown class with ports a person added, or an interface model's
                    AtomicNode added;
                    part.name = n.nodeName.isEmpty() ? n.execName : n.nodeName;
                    part.ports = resolvePorts(added, n, nullptr);
                } else if (cls) {
                    part.name = runtimeNodeName(*cls, n);
                    for (const Port &p : cls->ports)
                        if (!itemList(p).isEmpty() && itemsPastBound(p, n)) {
                            Diagnostic d;
                            d.severity = Diagnostic::Severity::Info;
                            d.code = QStringLiteral("evaluation-limit");
                            d.message =
                                QStringLiteral("%1 lists more than %2 names in %3: port %4 is "
                                               "made for the first %2, one port stands for the "
                                               "rest, its name undecided.")
                                    .arg(part.name)
                                    .arg(kMaxItemsPerList)
                                    .arg(itemList(p), p.id);
                            d.evidence = n.evidence;
                            arch.diagnostics.append(d);
                        }
                    const NodeInstance *container = nullptr;
                    if (!n.container.isEmpty())
                        container = instances.value(n.container, byName.value(n.container));
                    if (std::any_of(cls->ports.cbegin(), cls->ports.cend(), [](const Port &p) {
                            return !loadedPluginClass(p).isEmpty();
                        })) { // names per loaded plugin: the class as this instance loads them
                        AtomicNode perPlugin = *cls;
                        perPlugin.ports = expandLoadedPlugins(cls->ports, n, pluginClasses);
                        part.ports = resolvePorts(perPlugin, n, container);
                    } else {
                        part.ports = resolvePorts(*cls, n, container);
                    }
                    part.ports += pluginPorts(pluginClasses, n, container);
                } else {
                    part.name = n.nodeName.isEmpty() ? n.execName : n.nodeName;
                }
            } else {
                const LaunchFileInstance &child = *launchInstances.value(e.id);
                part.kind = RosNodePart::Kind::Launch;
                part.typeName = launchStem(child.type);
                part.typeId = child.id;
                part.nameSpace = RosNames::scopeRelative(namespaceOfInclude(lf, child.id));
                part.active = child.active && lf.active;
                part.external = child.external;
                part.typed = !child.external;
                // An external launch file an interface model describes: the ports of its
                // nodes, under the namespace the include gives them.
                for (const Port &p : child.modelledPorts) {
                    PartPort pp;
                    pp.id = p.id;
                    pp.kind = p.kind;
                    pp.nameAsWritten = p.name;
                    pp.name = RosNames::scopeRelative(
                        RosNames::expand(p.name, child.modelNamespace, QString()));
                    pp.type = p.type;
                    pp.evidence = p.evidence;
                    pp.model = child.interfaceModel;
                    part.ports.append(pp);
                }
                const auto it = built.constFind(child.id);
                if (it != built.constEnd()) {
                    for (const BoundaryPort &b : it->boundary) {
                        PartPort pp;
                        pp.id = b.id;
                        pp.kind = b.kind;
                        pp.name = b.name;
                        pp.type = b.type;
                        pp.guessed = b.guessed;
                        part.ports.append(pp);
                    }
                }
            }
            if (!renamed.isEmpty() && part.kind == RosNodePart::Kind::Node)
                for (PartPort &pp : part.ports)
                    if (const auto it = renamed.constFind(channelKey(pp.kind, pp.name));
                        it != renamed.cend()) {
                        pp.name = *it;
                        pp.marks.provenance = Provenance::Corrected;
                    }
            c.parts.append(part);
        }
        wire(&c);
        built.insert(lf.id, c);
        control.report(total - i, total, lf.type);
    }
    for (const LaunchFileInstance &lf : launch.instances)
        arch.composites.append(built.take(lf.id));
    return arch;
}

} // namespace rosarch
