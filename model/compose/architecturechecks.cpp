#include "architecturechecks.h"
#include "composer.h"
#include "rosnames.h"

#include <QHash>
#include <QSet>

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

QString familyName(PortKind k)
{
    switch (k) {
    case PortKind::Publisher:
    case PortKind::Subscriber:
        return QStringLiteral("topic");
    case PortKind::ServiceServer:
    case PortKind::ServiceClient:
        return QStringLiteral("service");
    default:
        return QStringLiteral("action");
    }
}

QString who(const RosNodePart &part)
{
    return RosNames::fullyQualified(part.nameSpace, part.name);
}

class Checker
{
public:
    Checker(const Architecture &arch, QList<Diagnostic> *out) : m_arch(arch), m_out(out) {}

    void checkRoot(const Composite &root)
    {
        m_system.clear();
        m_order.clear();
        collect(root, 0);
        for (const QString &key : std::as_const(m_order))
            checkName(key, root);
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
                if (const Composite *child = m_arch.composite(part.typeId))
                    collect(*child, depth + 1);
                continue;
            }
            for (const PartPort &port : part.ports) {
                if (!port.active || !port.resolved)
                    continue;
                const QString key = familyName(port.kind) + QLatin1Char(' ') + port.name;
                if (!m_system.contains(key))
                    m_order.append(key);
                Family &f = m_system[key];
                (isProvidingPort(port.kind) ? f.providers : f.users).append({&part, &port});
            }
        }
    }

    void add(Diagnostic::Severity severity, const QString &code, const QString &message,
             const Evidence &evidence)
    {
        Diagnostic d{severity, code, message, evidence};
        const QString key = code + message + evidence.file + QString::number(evidence.line);
        if (m_seen.contains(key))
            return;
        m_seen.insert(key);
        m_out->append(d);
    }

    void checkName(const QString &key, const Composite &root)
    {
        const Family &f = m_system.value(key);
        const QString kind = key.section(QLatin1Char(' '), 0, 0);
        const QString name = key.section(QLatin1Char(' '), 1);
        const QString system = root.file.isEmpty() ? root.stem : root.file;
        QStringList types;
        for (const QList<Use> *list : {&f.providers, &f.users})
            for (const Use &u : *list)
                if (!u.port->type.isEmpty() && !types.contains(u.port->type))
                    types.append(u.port->type);
        if (types.size() > 1) {
            const Use &u = f.providers.isEmpty() ? f.users.first() : f.providers.first();
            add(Diagnostic::Severity::Warning, QStringLiteral("type-mismatch"),
                QStringLiteral("The %1 %2 is used with different types in %3: %4.")
                    .arg(kind, name, system, types.join(QStringLiteral(", "))),
                u.port->evidence);
        }
        if (kind == QLatin1String("topic")) {
            if (f.providers.isEmpty())
                for (const Use &u : f.users)
                    add(Diagnostic::Severity::Warning, QStringLiteral("topic-unpublished"),
                        QStringLiteral(
                            "%1 subscribes to %2, which no node started by %3 publishes.")
                            .arg(who(*u.part), name, system),
                        u.port->evidence);
            if (f.users.isEmpty())
                for (const Use &u : f.providers)
                    add(Diagnostic::Severity::Info, QStringLiteral("topic-unheard"),
                        QStringLiteral(
                            "%1 publishes %2, which no node started by %3 subscribes to.")
                            .arg(who(*u.part), name, system),
                        u.port->evidence);
            return;
        }
        if (f.providers.size() > 1) {
            QStringList servers;
            for (const Use &u : f.providers)
                servers << who(*u.part);
            add(Diagnostic::Severity::Warning, QStringLiteral("duplicate-server"),
                QStringLiteral("The %1 %2 has %3 servers in %4: %5.")
                    .arg(kind, name)
                    .arg(f.providers.size())
                    .arg(system, servers.join(QStringLiteral(", "))),
                f.providers.at(1).port->evidence);
        }
        if (f.providers.isEmpty())
            for (const Use &u : f.users)
                add(Diagnostic::Severity::Info, QStringLiteral("unserved-client"),
                    QStringLiteral("%1 calls the %2 %3, which no node started by %4 serves.")
                        .arg(who(*u.part), kind, name, system),
                    u.port->evidence);
    }

    const Architecture &m_arch;
    QList<Diagnostic> *m_out;
    QHash<QString, Family> m_system;
    QStringList m_order;
    QSet<QString> m_seen;
};

/// A remap rule is reported when no instance carrying it has a port it renames; the
/// evidence is the first node the rule applies to.
void checkRemaps(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                 QList<Diagnostic> *out)
{
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
        if (!cls || !n.active)
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
            out->append({Diagnostic::Severity::Warning, QStringLiteral("remap-unmatched"),
                         QStringLiteral("The remap %1 matches no port of the nodes it applies to.")
                             .arg(r.text),
                         r.evidence});
}

} // namespace

QList<Diagnostic> ArchitectureChecks::run(const Architecture &arch, const AtomicNodeList &nodes,
                                          const LaunchDependencies &launch)
{
    QList<Diagnostic> out;
    Checker checker(arch, &out);
    for (const Composite &c : arch.composites)
        if (c.parentId.isEmpty())
            checker.checkRoot(c);
    checkRemaps(nodes, launch, &out);
    // A file included twice reports the same remap (same launch line) twice.
    QList<Diagnostic> unique;
    for (const Diagnostic &d : std::as_const(out))
        if (!unique.contains(d))
            unique.append(d);
    return unique;
}

} // namespace rosarch
