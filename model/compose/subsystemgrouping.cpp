#include "compose/subsystemgrouping.h"

#include <QHash>
#include <QSet>

namespace rosarch {

QString SubsystemGrouping::rootOf(const Architecture &architecture, const QString &instanceId)
{
    QString id = instanceId;
    QSet<QString> seen; // a malformed parent chain must not loop forever
    while (const Composite *c = architecture.composite(id)) {
        if (c->parentId.isEmpty() || seen.contains(id))
            return id;
        seen.insert(id);
        id = c->parentId;
    }
    return {};
}

Architecture SubsystemGrouping::apply(const Architecture &architecture,
                                      const QList<SubsystemGroup> &groups)
{
    Architecture out = architecture;
    if (groups.isEmpty())
        return out;
    for (Composite &c : out.composites) {
        const QString root = rootOf(architecture, c.instanceId);
        // Member instance -> group name, first group wins, for the groups below this root.
        QHash<QString, QString> groupOf;
        for (const SubsystemGroup &g : groups) {
            if (g.name.isEmpty() || (!g.rootId.isEmpty() && g.rootId != root))
                continue;
            for (const QString &member : g.memberInstanceIds)
                if (!groupOf.contains(member))
                    groupOf.insert(member, g.name);
        }
        if (groupOf.isEmpty())
            continue;
        for (RosNodePart &part : c.parts)
            if (part.kind == RosNodePart::Kind::Node && part.subsystem.isEmpty())
                part.subsystem = groupOf.value(part.instanceId);
    }
    // A launch file's classifier shows the grouping of the same node, started by the same
    // launch line, in the system.
    auto keyOf = [](const Composite &c, const RosNodePart &part) {
        return QStringLiteral("%1|%2|%3:%4|%5")
            .arg(c.file, part.evidence.file)
            .arg(part.evidence.line)
            .arg(part.evidence.column)
            .arg(part.name);
    };
    QHash<QString, QString> grouped;
    for (const Composite &c : std::as_const(out.composites))
        for (const RosNodePart &part : c.parts)
            if (!part.subsystem.isEmpty() && !grouped.contains(keyOf(c, part)))
                grouped.insert(keyOf(c, part), part.subsystem);
    if (grouped.isEmpty())
        return out;
    for (Composite &c : out.classifiers)
        for (RosNodePart &part : c.parts)
            if (part.kind == RosNodePart::Kind::Node && part.subsystem.isEmpty())
                part.subsystem = grouped.value(keyOf(c, part));
    return out;
}

} // namespace rosarch
