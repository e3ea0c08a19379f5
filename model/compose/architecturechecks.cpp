#include "compose/architecturechecks.h"
#include "compose/checkscope.h"
#include "compose/composer.h"
#include "compose/parameterchecks.h"
#include "compose/remapchecks.h"
#include "compose/systemports.h"
#include "core/qos.h"
#include "core/rosnames.h"
#include "interfaces/observability.h"

#include <QHash>
#include <QSet>

#include <algorithm>
#include <cstdlib>

namespace rosarch {

namespace {

using Use = PortUse;
using Family = PortFamily;

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
                        m_remapsAt[place(p.evidence)].append(
                            {n.id, n.classId, from, to, n.evidence});
            }
        }
    }

    void checkRoot(const Composite &root)
    {
        m_ports.clear();
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
        for (const QString &key : m_ports.keys())
            checkName(key);
        checkNodeNames();
        if (m_ports.hintsCut() && m_cutAt.isEmpty())
            m_cutAt = m_current;
    }

    /// The system whose checks spent the budget of the search for misspelt names ("" when
    /// none did): from there on, open ports were judged without that evidence.
    const QString &hintsCutAt() const { return m_cutAt; }

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
                    m_ports.add(part);
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
            m_ports.add(part);
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

    /// Why an open port (nobody on the other side in the system) is probably a mistake, and
    /// not the system's interface to something that runs beside it (a driver, a tool, an
    /// operator, the rest of a system this launch file is a part of), which the code alone
    /// cannot tell apart: a finding kind ships only when nine in ten of its findings are true
    /// (blueprint §1). The evidence, as a hint to append to the finding, with its places in
    /// `related`:
    /// - another launch file remaps this port where it starts a node of the same class, and
    ///   this one keeps the name as written: it may be missing that remap;
    /// - a name on the other side that this one is likely a misspelling of, of the same type
    ///   where both types are known, of another node;
    /// - the same name in another namespace on the other side, open too and of the same type
    ///   (`/robot1/goal_pose` and `/goal_pose`): a namespace pushed once too often, or not at
    ///   all.
    /// "" when there is none, and always for a port an interface model gives (code outside the
    /// workspace may use only some of it). `like` is the misspelled name found, if any.
    QString evidenceOfMistake(const QString &family, const QString &name, const Use &u,
                              QList<Diagnostic::Related> *related, QString *like) const
    {
        if (!u.port->model.isEmpty())
            return {};
        if (QString h = missingRemap(family, u, related); !h.isEmpty())
            return h;
        if (m_lone) // a building block's ports are its interface
            return {};
        const bool wantProviders = !isProvidingPort(u.port->kind);
        const Use *other = m_ports.misspelling(family, name, wantProviders, u.part, like);
        if (!other || !typesAgree(*other->port, *u.port))
            other = m_ports.namespaceSlip(family, name, u, wantProviders, like);
        // a debug or visualisation output is no counterpart anybody meant
        if (!other || (wantProviders && isObservability(*other->port))) {
            like->clear();
            return {};
        }
        const bool topic = family == QLatin1String("topic");
        related->append(Checker::related(
            *other, wantProviders
                        ? (topic ? QStringLiteral("publishes") : QStringLiteral("serves"))
                        : (topic ? QStringLiteral("subscribes to") : QStringLiteral("calls"))));
        return QStringLiteral(" Did you mean %1?").arg(*like);
    }

    /// " <file>:<line> remaps it … <file> starts this one without that remap." when another
    /// launch file remaps this port (made at the same place in the code) where it starts a
    /// node of the same class, and this instance keeps the name as written: no rule of its
    /// own names the port, not even one to a value the analysis could not decide. An output
    /// left unremapped harms nobody unless the name the other file gives it is heard here. (A
    /// remapped port whose target differs from another file's is no evidence: generic nodes
    /// such as filters are wired differently in every place they are started. Nor is a port
    /// whose guard the analysis could not decide: it may not exist.)
    QString missingRemap(const QString &family, const Use &u,
                         QList<Diagnostic::Related> *related) const
    {
        if (u.port->remapped || u.port->nameAsWritten.isEmpty() || !existsSurely(u))
            return {};
        const QString written = probed(u.port->nameAsWritten);
        const NodeInstance *instance = m_instances.value(u.part->instanceId);
        if (instance)
            for (const auto &[from, to] : instance->remaps)
                if (probed(from) == written)
                    return {};
        const bool output = isProvidingPort(u.port->kind);
        for (const RemapElsewhere &r : m_remapsAt.value(place(u.port->evidence))) {
            // a rule to an empty name (an argument nobody sets) shows no name to wire to
            if (r.evidence.file == u.part->evidence.file || r.classId != u.part->typeId ||
                r.to.isEmpty() || probed(r.from) != written)
                continue;
            if (output && m_ports
                              .family(family + QLatin1Char(' ') +
                                      RosNames::expand(r.to, u.part->nameSpace, u.part->name))
                              .users.isEmpty())
                continue;
            related->append({QStringLiteral("another launch file remaps %1 to %2 where it "
                                            "starts a node with this port")
                                 .arg(r.from, r.to),
                             r.evidence});
            return QStringLiteral(" %1:%2 remaps it (%3:=%4) where it starts a node of the "
                                  "same class; %5 starts this one without that remap.")
                .arg(r.evidence.file)
                .arg(r.evidence.line)
                .arg(r.from, r.to, u.part->evidence.file);
        }
        return {};
    }

    /// Whether the port exists in this instance for sure: no guard, or one the composition
    /// decided (a guard over several values, or on a value nobody gives, may be false).
    bool existsSurely(const Use &u) const
    {
        if (u.port->guard.isEmpty())
            return true;
        const AtomicNode *cls = m_nodes.node(u.part->typeId);
        const NodeInstance *instance = m_instances.value(u.part->instanceId);
        if (!cls || !instance)
            return false;
        for (const Port &p : cls->ports)
            if (p.id == u.port->id)
                return Composer::guardDecided(p, *instance);
        return false; // a plugin's port: its id is prefixed
    }

    /// Two ports' types are no reason against wiring them: equal, or one not known as ROS
    /// names it.
    static bool typesAgree(const PartPort &a, const PartPort &b)
    {
        return a.type == b.type || !isCanonicalInterfaceType(a.type) ||
               !isCanonicalInterfaceType(b.type);
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

    /// The first port of `first`, else of `then`, whose type is known as ROS names it.
    static const Use &typed(const QList<Use> &first, const QList<Use> &then)
    {
        for (const QList<Use> *list : {&first, &then})
            for (const Use &u : *list)
                if (isCanonicalInterfaceType(u.port->type))
                    return u;
        return first.first();
    }

    void checkName(const QString &key)
    {
        const Family f = m_ports.family(key);
        const QString kind = key.section(QLatin1Char(' '), 0, 0);
        const QString name = key.section(QLatin1Char(' '), 1);
        QStringList types;
        // An expression left as written is no type to compare; a node that runs only by a
        // guess may be the alternative of the other type (an `if` in the launch file or in the
        // main that builds the nodes).
        for (const QList<Use> *list : {&f.providers, &f.users})
            for (const Use &u : *list)
                if (isCanonicalInterfaceType(u.port->type) && !types.contains(u.port->type) &&
                    !runsByGuess(*u.part))
                    types.append(u.port->type);
        if (types.size() > 1) {
            const Use &u = typed(f.providers.isEmpty() ? f.users : f.providers, f.users);
            QList<Diagnostic::Related> others;
            for (const QList<Use> *list : {&f.providers, &f.users})
                for (const Use &o : *list)
                    if (o.port != u.port && isCanonicalInterfaceType(o.port->type) &&
                        o.port->type != u.port->type)
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
                checkOpen(kind, name, f.users);
            if (f.users.isEmpty())
                checkOpen(kind, name, f.providers);
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
            checkOpen(kind, name, f.users);
    }

    /// The ports of `side` on a name nobody uses from the other side that evidence says are
    /// probably a mistake (evidenceOfMistake): `topic-unpublished`, `topic-unheard` or
    /// `unserved-client`, or `remap-target-unused` when a remap rule gave the port its name.
    void checkOpen(const QString &kind, const QString &name, const QList<Use> &side)
    {
        const bool topic = kind == QLatin1String("topic");
        for (const Use &u : side) {
            const bool output = isProvidingPort(u.port->kind);
            // Meant for tools (RViz, ros2 bag, plotters): nobody in the system needs to hear it.
            if ((output && isObservability(*u.port)) || m_scope.isInterface(name, output))
                continue;
            QList<Diagnostic::Related> rel;
            QString like;
            const QString h = evidenceOfMistake(kind, name, u, &rel, &like);
            if (h.isEmpty())
                continue;
            // A misspelled pair is one finding, at the input that misses its data (unless
            // that input is an interface model's, which reports nothing).
            if (output && !like.isEmpty()) {
                const Family pair = m_ports.family(kind + QLatin1Char(' ') + like);
                if (pair.providers.isEmpty() &&
                    std::any_of(pair.users.cbegin(), pair.users.cend(),
                                [](const Use &o) { return o.port->model.isEmpty(); }))
                    continue;
            }
            if (u.port->remapped) {
                remapTargetUnused(u, name,
                                  !topic   ? QStringLiteral("serves")
                                  : output ? QStringLiteral("subscribes to")
                                           : QStringLiteral("publishes"),
                                  h, rel);
                continue;
            }
            if (!topic)
                add(Diagnostic::Severity::Info, QStringLiteral("unserved-client"),
                    QStringLiteral("%1 calls the %2 %3, which no node started {by} serves.%4")
                        .arg(who(*u.part), kind, name, h),
                    u.port->evidence, rel, CheckScope::externalOf(name, false));
            else if (output)
                add(Diagnostic::Severity::Info, QStringLiteral("topic-unheard"),
                    QStringLiteral("%1 publishes %2, which no node started {by} subscribes to.%3")
                        .arg(who(*u.part), name, h),
                    u.port->evidence, rel, CheckScope::externalOf(name, true));
            else
                add(Diagnostic::Severity::Warning, QStringLiteral("topic-unpublished"),
                    QStringLiteral("%1 subscribes to %2, which no node started {by} publishes.%3")
                        .arg(who(*u.part), name, h),
                    u.port->evidence, rel, CheckScope::externalOf(name, false));
        }
    }

    /// A port a remap rule renamed, to a name nobody on the other side uses: the finding is
    /// the rule (at the launch line), with the port's creation as the related place.
    void remapTargetUnused(const Use &u, const QString &name, const QString &counterpart,
                           const QString &h, QList<Diagnostic::Related> rel)
    {
        rel.prepend({QStringLiteral("%1 %2 as written in the code")
                         .arg(portKindName(u.port->kind), u.port->nameAsWritten),
                     u.port->evidence});
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
            // One launch action started them all: an executable whose code builds several
            // nodes, given a name, which ROS 2 applies to every node of the process.
            const bool oneAction =
                std::all_of(parts.cbegin(), parts.cend(), [&](const RosNodePart *p) {
                    const NodeInstance *n = m_instances.value(p->instanceId);
                    return p->evidence == parts.first()->evidence && n && n->namedByLaunch;
                });
            if (oneAction) {
                QStringList types;
                for (const RosNodePart *p : parts)
                    types << p->typeName;
                add(Diagnostic::Severity::Warning, QStringLiteral("process-renamed"),
                    QStringLiteral("This launch action names the node %1, but its executable "
                                   "builds %2 nodes in its own code (%3){in}: ROS 2 gives the "
                                   "name to every node of the process, so they all are %1.")
                        .arg(fq)
                        .arg(parts.size())
                        .arg(types.join(QStringLiteral(", "))),
                    parts.first()->evidence, rel);
                continue;
            }
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
        QString instanceId, classId, from, to;
        Evidence evidence; ///< the node in its launch file
    };
    QHash<QString, QList<RemapElsewhere>> m_remapsAt; ///< a port's place -> remaps of it
    QList<Diagnostic> *m_out;
    SystemPorts m_ports; ///< of the system being checked
    QString m_cutAt;
    QHash<QString, QList<const RosNodePart *>> m_named; ///< fully qualified name -> parts
    QStringList m_nodeOrder;
    QHash<QString, int> m_seen; ///< a finding's text and place -> its index in m_out
    QString m_current;          ///< the system being checked
    int m_nodeCount = 0; ///< active node parts of the system being checked that it starts itself
    bool m_lone = false; ///< the system starts fewer than two nodes
};

} // namespace

QList<Diagnostic> ArchitectureChecks::run(const Architecture &arch, const AtomicNodeList &nodes,
                                          const LaunchDependencies &launch,
                                          const Observability &observability)
{
    QList<Diagnostic> out;
    Checker checker(arch, nodes, launch, observability, &out);
    for (const Composite &c : arch.composites)
        if (c.parentId.isEmpty() && CheckScope::isJudged(launch, c.file))
            checker.checkRoot(c);
    if (!checker.hintsCutAt().isEmpty()) {
        Diagnostic d;
        d.severity = Diagnostic::Severity::Info;
        d.code = QStringLiteral("check-limit");
        d.message = QStringLiteral("The search for misspelt names spent its budget (%1 letters "
                                   "compared) in the system of %2: open ports judged after that "
                                   "were judged without it, so a misspelling may go unreported.")
                        .arg(SystemPorts::kHintBudget)
                        .arg(checker.hintsCutAt());
        out.append(d);
    }
    RemapChecks::run(nodes, launch, &out);
    ParameterChecks::run(nodes, launch, &out);
    // A file included twice reports the same remap (same launch line) twice.
    Diagnostic::removeDuplicates(&out);
    return out;
}

} // namespace rosarch
