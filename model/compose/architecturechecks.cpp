#include "architecturechecks.h"
#include "checkscope.h"
#include "composer.h"
#include "editdistance.h"
#include "observability.h"
#include "qos.h"
#include "rosnames.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <cstdlib>

namespace rosarch {

namespace {

struct Use
{
    const RosNodePart *part;
    const PartPort *port;
};

struct Family
{
    QList<Use> providers; ///< publishers, servers
    QList<Use> users;     ///< subscribers, clients
};

QString who(const RosNodePart &part)
{
    return RosNames::fullyQualified(part.nameSpace, part.name);
}

class Checker
{
public:
    Checker(const Architecture &arch, const AtomicNodeList &nodes, const LaunchDependencies &launch,
            const Observability &observability, QList<Diagnostic> *out)
        : m_nodes(nodes), m_observability(observability), m_scope(launch), m_out(out)
    {
        for (const Composite &c : arch.composites)
            if (!m_composites.contains(c.instanceId)) // the first, as Architecture::composite()
                m_composites.insert(c.instanceId, &c);
        for (const NodeInstance &n : launch.nodes)
            m_instances.insert(n.id, &n); // LaunchDependencies::node() is a linear search
        // The helper that creates a port, by the port's place in the code (a part's port
        // carries the evidence of the atomic port it comes from).
        for (const AtomicNode &n : nodes.nodes)
            for (const Port &p : n.ports)
                if (!p.via.isEmpty())
                    m_helpers.insert(place(p.evidence), p.via);
        // Every remap rule a launch file gives a port, by the port's place in the code (one
        // helper may create the port for several classes), in launch order.
        for (const NodeInstance &n : launch.nodes) {
            const AtomicNode *cls = nodes.node(n.classId);
            if (!cls)
                continue;
            for (const auto &[from, to] : n.remaps) {
                if (!RosNames::isNameRule(from))
                    continue;
                const QString rule = probed(from);
                for (const Port &p : cls->ports)
                    if (probed(p.name) == rule)
                        m_remapsAt[place(p.evidence)].append({n.id, from, to, n.evidence});
            }
        }
    }

    void checkRoot(const Composite &root)
    {
        m_system.clear();
        m_order.clear();
        m_named.clear();
        m_nodeOrder.clear();
        m_nodeCount = 0;
        m_current = systemName(root);
        m_scope.enterSystem(root.file);
        collect(root, 0);
        // A launch file that starts one node is a building block, not a system: every port
        // of that node is its interface to whatever runs beside it, so nothing is missing.
        // Its child nodes run in its process, and a component container (a node without
        // ports or a class) only hosts it: neither makes the file a system.
        m_lone = m_nodeCount < 2;
        for (const QString &key : std::as_const(m_order))
            checkName(key);
        checkNodeNames();
    }

private:
    void collect(const Composite &c, int depth)
    {
        if (depth > 64)
            return;
        for (const RosNodePart &part : c.parts) {
            if (!part.active)
                continue;
            if (part.kind == RosNodePart::Kind::Launch) {
                if (part.external) // an interface model's ports, if one describes it
                    addPorts(part);
                else if (const Composite *child = m_composites.value(part.typeId))
                    collect(*child, depth + 1);
                continue;
            }
            if (startsProcessWithPorts(part))
                ++m_nodeCount;
            if (nameIsKnown(part)) {
                const QString fq = who(part);
                if (!m_named.contains(fq))
                    m_nodeOrder.append(fq);
                m_named[fq].append(&part);
            }
            addPorts(part);
        }
    }

    void addPorts(const RosNodePart &part)
    {
        for (const PartPort &port : part.ports) {
            if (!port.active || !port.resolved || port.guessed)
                continue; // a guessed name proves nothing about who hears whom
            const QString key = portFamilyName(port.kind) + QLatin1Char(' ') + port.name;
            if (!m_system.contains(key))
                m_order.append(key);
            Family &f = m_system[key];
            (isProvidingPort(port.kind) ? f.providers : f.users).append({&part, &port});
        }
    }

    /// Records a finding of the current system. `message` may name the system with "{by}"
    /// ("started {by} publishes") and "{in}" (" in the system"): the finding itself says
    /// "alongside it" and lists the system among its contexts, so that one finding seen in N
    /// systems is reported once with N contexts. The per-system wording it had before is kept
    /// as an alias key (old baselines and project files still match it).
    void add(Diagnostic::Severity severity, const QString &code, const QString &message,
             const Evidence &evidence, const QList<Diagnostic::Related> &related = {},
             const QString &external = {})
    {
        const QString text = QString(message)
                                 .replace(QLatin1String("{by}"), QLatin1String("alongside it"))
                                 .replace(QLatin1String("{in}"), QString());
        const Diagnostic old{severity,
                             code,
                             QString(message)
                                 .replace(QLatin1String("{by}"), QLatin1String("by ") + m_current)
                                 .replace(QLatin1String("{in}"), QLatin1String(" in ") + m_current),
                             evidence,
                             {},
                             {},
                             {}};
        const QString key = code + QLatin1Char('\n') + text + QLatin1Char('\n') + evidence.file +
                            QLatin1Char(':') + QString::number(evidence.line);
        if (const auto it = m_seen.constFind(key); it != m_seen.cend()) {
            Diagnostic &d = (*m_out)[*it];
            if (!d.contexts.contains(m_current))
                d.contexts.append(m_current);
            if (const QString alias = old.key(); !d.aliases.contains(alias))
                d.aliases.append(alias);
            for (const Diagnostic::Related &r : related)
                if (!d.related.contains(r))
                    d.related.append(r);
            return;
        }
        m_seen.insert(key, int(m_out->size()));
        m_out->append(
            {severity, code, text, evidence, related, {m_current}, {old.key()}, external});
    }

    /// Whether an open port is open by design, and not a finding: a port an interface model
    /// gives (code outside the workspace may use only some of it), and any port of a launch
    /// file that starts one node (a building block: its ports are its interface), unless
    /// another launch file remaps that port (created at the same place in the code) where it
    /// starts a node. Then this file probably misses the remap: `hint` and `related` say which
    /// and where.
    bool openByDesign(const Use &u, QList<Diagnostic::Related> *related, QString *hint) const
    {
        if (!u.port->model.isEmpty())
            return true;
        if (!m_lone)
            return false;
        if (u.port->remapped || u.port->nameAsWritten.isEmpty())
            return true;
        const QString written = probed(u.port->nameAsWritten);
        for (const RemapElsewhere &r : m_remapsAt.value(place(u.port->evidence))) {
            if (r.instanceId == u.part->instanceId || probed(r.from) != written)
                continue;
            related->append({QStringLiteral("another launch file remaps %1 to %2 where it "
                                            "starts a node with this port")
                                 .arg(r.from, r.to),
                             r.evidence});
            *hint = QStringLiteral(" %1:%2 remaps it (%3:=%4) where it starts a node with this "
                                   "port; this launch file may be missing that remap.")
                        .arg(r.evidence.file)
                        .arg(r.evidence.line)
                        .arg(r.from, r.to);
            return false;
        }
        return true;
    }

    /// A debug, visualisation, diagnostics or processing-time output, by its resolved name or
    /// its name as written (`~/debug/x` remapped to `/x`), its type or its helper.
    bool isObservability(const PartPort &port) const
    {
        const QString helper = m_helpers.value(place(port.evidence));
        return m_observability.covers(port.name, port.type, helper) ||
               m_observability.covers(port.nameAsWritten, port.type, helper) ||
               m_scope.isViewed(port.name);
    }

    /// A name expanded in one made-up namespace and node name, to compare two spellings.
    static QString probed(const QString &name)
    {
        return RosNames::expand(name, QStringLiteral("/__probe"), QStringLiteral("__node"));
    }

    static QString place(const Evidence &e)
    {
        return QStringLiteral("%1:%2:%3").arg(e.file).arg(e.line).arg(e.column);
    }

    static QString systemName(const Composite &root)
    {
        return root.file.isEmpty() ? root.stem : root.file;
    }

    static Diagnostic::Related related(const Use &u, const QString &role)
    {
        return {QStringLiteral("%1 %2 %3%4")
                    .arg(who(*u.part), role, u.port->name,
                         u.port->type.isEmpty() ? QString()
                                                : QStringLiteral(" (%1)").arg(u.port->type)),
                u.port->evidence};
    }

    /// The existing name of the same family most like `name` (edit distance), among those
    /// with a provider when `wantProviders`, else among those with users; "" when none is
    /// close enough to be a likely misspelling.
    const Use *nearest(const QString &family, const QString &name, bool wantProviders,
                       QString *found) const
    {
        // A name this long is no misspelling a person would make; and past a run's budget of
        // work (cells of the distance and names looked at), hints stop, so they stay linear.
        if (name.size() > 256 || m_hintWork > 50'000'000)
            return nullptr;
        const QString bare = name.section(QLatin1Char('/'), -1);
        int best = std::max(2, int(bare.size()) / 3) + 1;
        const Use *use = nullptr;
        const QString prefix = family + QLatin1Char(' ');
        for (const QString &key : m_order) {
            ++m_hintWork;
            if (!key.startsWith(prefix))
                continue;
            const QStringView other = QStringView(key).mid(prefix.size());
            // the distance is at least the difference in length: most names are out at once
            if (std::abs(other.size() - name.size()) >= best || other == name)
                continue;
            const auto it = m_system.constFind(key);
            const QList<Use> &side = wantProviders ? it->providers : it->users;
            if (side.isEmpty())
                continue;
            m_hintWork += other.size() * (2 * best + 1);
            const int d = editDistance(name, other.toString(), best);
            if (d < best) {
                best = d;
                use = &side.first();
                *found = other.toString();
            }
        }
        return use;
    }

    /// " Did you mean /x?" and its place, when a name like `name` exists on the other side.
    QString hint(const QString &family, const QString &name, bool wantProviders,
                 QList<Diagnostic::Related> *related) const
    {
        QString found;
        const Use *u = nearest(family, name, wantProviders, &found);
        if (!u)
            return {};
        related->append(Checker::related(*u, wantProviders ? (family == QLatin1String("topic")
                                                                  ? QStringLiteral("publishes")
                                                                  : QStringLiteral("serves"))
                                                           : QStringLiteral("subscribes to")));
        return QStringLiteral(" Did you mean %1?").arg(found);
    }

    void checkName(const QString &key)
    {
        const Family &f = m_system.value(key);
        const QString kind = key.section(QLatin1Char(' '), 0, 0);
        const QString name = key.section(QLatin1Char(' '), 1);
        QStringList types;
        for (const QList<Use> *list : {&f.providers, &f.users})
            for (const Use &u : *list)
                if (!u.port->type.isEmpty() && !types.contains(u.port->type))
                    types.append(u.port->type);
        if (types.size() > 1) {
            const Use &u = f.providers.isEmpty() ? f.users.first() : f.providers.first();
            QList<Diagnostic::Related> others;
            for (const QList<Use> *list : {&f.providers, &f.users})
                for (const Use &o : *list)
                    if (o.port != u.port && !o.port->type.isEmpty() && o.port->type != u.port->type)
                        others << related(o, isProvidingPort(o.port->kind)
                                                 ? QStringLiteral("provides")
                                                 : QStringLiteral("uses"));
            add(Diagnostic::Severity::Warning, QStringLiteral("type-mismatch"),
                QStringLiteral("The %1 %2 is used with different types{in}: %3.")
                    .arg(kind, name, types.join(QStringLiteral(", "))),
                u.port->evidence, others);
        }
        if (kind == QLatin1String("topic")) {
            checkQos(name, f);
            if (f.providers.isEmpty())
                for (const Use &u : f.users) {
                    QList<Diagnostic::Related> rel;
                    QString h;
                    if (m_scope.isInterface(name, false) || openByDesign(u, &rel, &h))
                        continue;
                    if (u.port->remapped) {
                        remapTargetUnused(u, name, QStringLiteral("publishes"));
                        continue;
                    }
                    if (h.isEmpty())
                        h = hint(kind, name, true, &rel);
                    add(Diagnostic::Severity::Warning, QStringLiteral("topic-unpublished"),
                        QStringLiteral(
                            "%1 subscribes to %2, which no node started {by} publishes.%3")
                            .arg(who(*u.part), name, h),
                        u.port->evidence, rel, CheckScope::externalOf(name, false));
                }
            if (f.users.isEmpty())
                for (const Use &u : f.providers) {
                    // Meant for tools (RViz, ros2 bag, plotters): nobody in the system needs
                    // to hear it.
                    if (isObservability(*u.port))
                        continue;
                    QList<Diagnostic::Related> rel;
                    QString h;
                    if (m_scope.isInterface(name, true) || openByDesign(u, &rel, &h))
                        continue;
                    if (u.port->remapped) {
                        remapTargetUnused(u, name, QStringLiteral("subscribes to"));
                        continue;
                    }
                    if (h.isEmpty())
                        h = hint(kind, name, false, &rel);
                    add(Diagnostic::Severity::Info, QStringLiteral("topic-unheard"),
                        QStringLiteral(
                            "%1 publishes %2, which no node started {by} subscribes to.%3")
                            .arg(who(*u.part), name, h),
                        u.port->evidence, rel, CheckScope::externalOf(name, true));
                }
            return;
        }
        // Two servers of which one may not run (its condition is a guess) may be alternatives.
        const bool twoServersRun =
            std::count_if(f.providers.cbegin(), f.providers.cend(),
                          [&](const Use &u) { return !runsByGuess(*u.part); }) > 1;
        if (f.providers.size() > 1 && twoServersRun) {
            QStringList servers;
            QList<Diagnostic::Related> rel;
            for (const Use &u : f.providers) {
                servers << who(*u.part);
                if (u.port != f.providers.at(1).port)
                    rel << related(u, QStringLiteral("serves"));
            }
            add(Diagnostic::Severity::Warning, QStringLiteral("duplicate-server"),
                QStringLiteral("The %1 %2 has %3 servers{in}: %4.")
                    .arg(kind, name)
                    .arg(f.providers.size())
                    .arg(servers.join(QStringLiteral(", "))),
                f.providers.at(1).port->evidence, rel);
        }
        if (f.providers.isEmpty())
            for (const Use &u : f.users) {
                QList<Diagnostic::Related> rel;
                QString h;
                if (m_scope.isInterface(name, false) || openByDesign(u, &rel, &h))
                    continue;
                if (u.port->remapped) {
                    remapTargetUnused(u, name, QStringLiteral("serves"));
                    continue;
                }
                if (h.isEmpty())
                    h = hint(kind, name, true, &rel);
                add(Diagnostic::Severity::Info, QStringLiteral("unserved-client"),
                    QStringLiteral("%1 calls the %2 %3, which no node started {by} serves.%4")
                        .arg(who(*u.part), kind, name, h),
                    u.port->evidence, rel, CheckScope::externalOf(name, false));
            }
    }

    /// A port a remap rule renamed, to a name nobody on the other side uses: the finding is
    /// the rule (at the launch line), with the port's creation as the related place.
    void remapTargetUnused(const Use &u, const QString &name, const QString &counterpart)
    {
        QList<Diagnostic::Related> rel{{QStringLiteral("%1 %2 as written in the code")
                                            .arg(portKindName(u.port->kind), u.port->nameAsWritten),
                                        u.port->evidence}};
        const QString family = portFamilyName(u.port->kind);
        const QString h = hint(family, name, !isProvidingPort(u.port->kind), &rel);
        // Like the unremapped findings: an input nobody feeds is a warning, an output
        // nobody hears (often meant for something outside the system) is a note.
        add(isProvidingPort(u.port->kind) ? Diagnostic::Severity::Info
                                          : Diagnostic::Severity::Warning,
            QStringLiteral("remap-target-unused"),
            QStringLiteral("%1 remaps its %2 %3 to %4, which no node started {by} %5.%6")
                .arg(who(*u.part), portKindName(u.port->kind), u.port->nameAsWritten, name,
                     counterpart, h),
            u.part->evidence, rel, CheckScope::externalOf(name, isProvidingPort(u.port->kind)));
    }

    /// Publisher and subscription pairs whose literal QoS cannot match (ROS 2's request/offer
    /// rules for reliability and durability); a side whose QoS is not written out is skipped.
    void checkQos(const QString &name, const Family &f)
    {
        for (const Use &sub : f.users) {
            const QosProfile requested = QosProfile::fromWritten(sub.port->qos);
            for (const Use &pub : f.providers) {
                const QString why =
                    QosProfile::incompatibility(QosProfile::fromWritten(pub.port->qos), requested);
                if (why.isEmpty())
                    continue;
                add(Diagnostic::Severity::Warning, QStringLiteral("qos-incompatible"),
                    QStringLiteral("%1 will not receive %2 from %3{in}: %4 (QoS %5 against %6).")
                        .arg(who(*sub.part), name, who(*pub.part), why, sub.port->qos,
                             pub.port->qos),
                    sub.port->evidence,
                    {related(pub, QStringLiteral("publishes with QoS %1 on").arg(pub.port->qos))});
            }
        }
    }

    /// Two nodes with one fully qualified name in a system: ROS 2 lets both start, and then
    /// parameters, services and tools reach either one.
    void checkNodeNames()
    {
        for (const QString &fq : std::as_const(m_nodeOrder)) {
            const QList<const RosNodePart *> &parts = m_named[fq];
            // Nodes of which one may not run (its condition is a guess) may be alternatives.
            if (parts.size() < 2 ||
                std::count_if(parts.cbegin(), parts.cend(),
                              [&](const RosNodePart *p) { return !runsByGuess(*p); }) < 2)
                continue;
            QList<Diagnostic::Related> rel;
            for (const RosNodePart *p : parts.mid(1))
                rel << Diagnostic::Related{
                    QStringLiteral("another %1 named %2").arg(p->typeName, fq), p->evidence};
            add(Diagnostic::Severity::Warning, QStringLiteral("duplicate-node-name"),
                QStringLiteral("%1 nodes are named %2{in}.").arg(parts.size()).arg(fq),
                parts.first()->evidence, rel);
        }
    }

    /// Whether the part runs only by the best guess: its condition, or that of a group or
    /// include around it, could not be decided (an argument nobody sets, say).
    /// A node the launch file starts itself (not a child node made by another node's code)
    /// that can take part in wiring: its class is known, or it has ports.
    bool startsProcessWithPorts(const RosNodePart &part) const
    {
        const NodeInstance *n = m_instances.value(part.instanceId);
        return (!n || n->parentNode.isEmpty()) && (part.typed || !part.ports.isEmpty());
    }

    bool runsByGuess(const RosNodePart &part) const
    {
        const NodeInstance *n = m_instances.value(part.instanceId);
        return n && n->activeByGuess;
    }

    /// The node name is what runs: given in the launch file, or in the node's code. A name
    /// guessed from the executable (a package outside the workspace, a computed name) is not.
    bool nameIsKnown(const RosNodePart &part) const
    {
        if (part.name.isEmpty())
            return false;
        const NodeInstance *instance = m_instances.value(part.instanceId);
        if (instance && !instance->nodeName.isEmpty())
            return true;
        const AtomicNode *cls = instance ? m_nodes.node(instance->classId) : nullptr;
        return cls && !cls->nodeName.isEmpty();
    }

    QHash<QString, const Composite *> m_composites;   ///< by instance id
    QHash<QString, const NodeInstance *> m_instances; ///< by id
    const AtomicNodeList &m_nodes;
    const Observability &m_observability;
    CheckScope m_scope;                ///< what is left to something outside the system
    QHash<QString, QString> m_helpers; ///< a port's place in the code -> the helper creating it
    struct RemapElsewhere
    {
        QString instanceId, from, to;
        Evidence evidence; ///< the node in its launch file
    };
    QHash<QString, QList<RemapElsewhere>> m_remapsAt; ///< a port's place -> remaps of it
    QList<Diagnostic> *m_out;
    QHash<QString, Family> m_system;
    QStringList m_order;
    mutable qint64 m_hintWork = 0;                      ///< of nearest(), in this run
    QHash<QString, QList<const RosNodePart *>> m_named; ///< fully qualified name -> parts
    QStringList m_nodeOrder;
    QHash<QString, int> m_seen; ///< a finding's text and place -> its index in m_out
    QString m_current;          ///< the system being checked
    int m_nodeCount = 0; ///< active node parts of the system being checked that it starts itself
    bool m_lone = false; ///< the system starts fewer than two nodes
};

/// A system the checks judge: a root launch-file instance of an entry point. Without entry
/// points (a composition of given instances), every root.
bool judged(const LaunchDependencies &launch, const QString &rootFile)
{
    return launch.entryPoints.isEmpty() || launch.entryPoints.contains(rootFile);
}

/// The launch-file instances of the judged systems: each root and what it includes.
QSet<QString> judgedInstances(const LaunchDependencies &launch)
{
    QSet<QString> in;
    for (const LaunchFileInstance &i : launch.instances) // roots first, then their includes
        if (i.parentId.isEmpty() ? judged(launch, i.file) : in.contains(i.parentId))
            in.insert(i.id);
    return in;
}

/// A remap rule is reported when no instance carrying it has a port it renames; the
/// evidence is the first node the rule applies to.
void checkRemaps(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                 QList<Diagnostic> *out)
{
    const QSet<QString> systems = judgedInstances(launch);
    struct Rule
    {
        QString text;
        Evidence evidence;
        bool used = false;
        bool decidable = true;
    };
    QList<Rule> rules;
    QHash<QString, int> index;
    for (const NodeInstance &n : launch.nodes) {
        const AtomicNode *cls = nodes.node(n.classId);
        if (!cls || !n.active || !systems.contains(n.launchFileId))
            continue;
        QList<int> used;
        Composer::resolvePorts(*cls, n, nullptr, &used);
        const bool allResolved = std::all_of(cls->ports.begin(), cls->ports.end(),
                                             [](const Port &p) { return p.isResolved(); });
        for (qsizetype i = 0; i < n.remaps.size(); ++i) {
            const auto &[from, to] = n.remaps.at(i);
            if (!RosNames::isNameRule(from))
                continue;
            // A scoped SetRemap reaches nodes of several files: the rule is judged as a whole.
            const QString key = from + QLatin1Char('\n') + to;
            int at = index.value(key, -1);
            if (at < 0) {
                at = int(rules.size());
                index.insert(key, at);
                rules.append({QStringLiteral("%1:=%2").arg(from, to), n.evidence});
            }
            rules[at].used = rules[at].used || used.contains(int(i));
            rules[at].decidable = rules[at].decidable && allResolved;
        }
    }
    for (const Rule &r : std::as_const(rules))
        if (!r.used && r.decidable)
            out->append({Diagnostic::Severity::Warning,
                         QStringLiteral("remap-unmatched"),
                         QStringLiteral("The remap %1 matches no port of the nodes it applies to.")
                             .arg(r.text),
                         r.evidence,
                         {}});
}

} // namespace

QList<Diagnostic> ArchitectureChecks::run(const Architecture &arch, const AtomicNodeList &nodes,
                                          const LaunchDependencies &launch,
                                          const Observability &observability)
{
    QList<Diagnostic> out;
    Checker checker(arch, nodes, launch, observability, &out);
    for (const Composite &c : arch.composites)
        if (c.parentId.isEmpty() && judged(launch, c.file))
            checker.checkRoot(c);
    checkRemaps(nodes, launch, &out);
    // A file included twice reports the same remap (same launch line) twice.
    Diagnostic::removeDuplicates(&out);
    return out;
}

} // namespace rosarch
