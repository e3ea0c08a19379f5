#include "suggestions/subsystemgrouper.h"

#include <QHash>
#include <QRegularExpression>
#include <QSet>

#include <algorithm>

namespace rosarch {

namespace {

/// Lower-case words of an identifier: snake_case, kebab-case, CamelCase and paths split.
QSet<QString> words(const QString &text)
{
    QString spaced = text;
    static const QRegularExpression camel(QStringLiteral("([a-z0-9])([A-Z])"));
    spaced.replace(camel, QStringLiteral("\\1 \\2"));
    QSet<QString> out;
    static const QRegularExpression separators(QStringLiteral("[^A-Za-z0-9]+"));
    for (const QString &w : spaced.toLower().split(separators, Qt::SkipEmptyParts)) {
        bool digits = false;
        w.toInt(&digits);
        if (w.size() > 1 && !digits)
            out.insert(w);
    }
    return out;
}

QSet<QString> instanceWords(const NodeInstance &n)
{
    QSet<QString> w = words(n.nodeName);
    w.unite(words(n.nameSpace));
    w.unite(words(n.package));
    w.unite(words(n.className));
    return w;
}

} // namespace

SubsystemGrouper::SubsystemGrouper(const Recovery &recovery) : m_recovery(recovery)
{
    for (const Composite &c : recovery.architecture.composites)
        for (const RosNodePart &p : c.parts)
            if (p.kind == RosNodePart::Kind::Node && !m_parts.contains(p.instanceId))
                m_parts.insert(p.instanceId, &p);
}

QStringList SubsystemGrouper::hubTopics()
{
    return {QStringLiteral("/tf"),
            QStringLiteral("/tf_static"),
            QStringLiteral("/rosout"),
            QStringLiteral("/parameter_events"),
            QStringLiteral("/clock"),
            QStringLiteral("/diagnostics"),
            QStringLiteral("/robot_description"),
            QStringLiteral("/robot_diagnostics")};
}

QStringList SubsystemGrouper::endpoints(const NodeInstance &instance) const
{
    QStringList out;
    const RosNodePart *part = m_parts.value(instance.id);
    if (!part)
        return out;
    for (const PartPort &p : part->ports) {
        if (!p.resolved || !p.active)
            continue;
        const char *role = "";
        switch (p.kind) {
        case PortKind::Publisher:
            role = "topic-out";
            break;
        case PortKind::Subscriber:
            role = "topic-in";
            break;
        case PortKind::ServiceServer:
            role = "service-out";
            break;
        case PortKind::ServiceClient:
            role = "service-in";
            break;
        case PortKind::ActionServer:
            role = "action-out";
            break;
        case PortKind::ActionClient:
            role = "action-in";
            break;
        }
        out << QString::fromLatin1(role) + QLatin1Char(' ') + p.name;
    }
    out.removeDuplicates();
    return out;
}

QList<SubsystemGrouper::Group> SubsystemGrouper::groups(const QStringList &instanceIds) const
{
    QList<const NodeInstance *> nodes;
    for (const QString &id : instanceIds)
        if (const NodeInstance *n = m_recovery.launch.node(id); n && n->active)
            nodes << n;
    const qsizetype count = nodes.size();

    // channel ("topic /x") -> producer and consumer indices
    QMap<QString, QPair<QList<int>, QList<int>>> channels;
    for (int i = 0; i < count; ++i)
        for (const QString &e : endpoints(*nodes[i])) {
            const qsizetype space = e.indexOf(QLatin1Char(' '));
            const QString role = e.left(space);
            const QString channel = role.section(QLatin1Char('-'), 0, 0) + e.mid(space);
            auto &entry = channels[channel];
            (role.endsWith(QLatin1String("-out")) ? entry.first : entry.second).append(i);
        }
    const QStringList hubs = hubTopics();
    const qsizetype hubDegree = qMax<qsizetype>(6, count / 2);
    QList<QMap<int, int>> weight(count);         // adjacency with shared-name counts
    QList<QMap<int, QStringList>> shared(count); // which names make each edge
    for (auto it = channels.cbegin(); it != channels.cend(); ++it) {
        const QString name = it.key().section(QLatin1Char(' '), 1);
        QSet<int> all(it->first.begin(), it->first.end());
        all.unite(QSet<int>(it->second.begin(), it->second.end()));
        if ((it.key().startsWith(QLatin1String("topic ")) && hubs.contains(name)) ||
            all.size() > hubDegree)
            continue;
        for (int p : it->first)
            for (int c : it->second)
                if (p != c) {
                    ++weight[p][c];
                    ++weight[c][p];
                    shared[p][c] << it.key();
                    shared[c][p] << it.key();
                }
    }

    // Asynchronous label propagation in artifact order; ties keep the current label, else the
    // smallest, so the result is deterministic.
    QList<int> label(count);
    for (int i = 0; i < count; ++i)
        label[i] = i;
    for (int round = 0; round < 100; ++round) {
        bool changed = false;
        for (int i = 0; i < count; ++i) {
            if (weight[i].isEmpty())
                continue;
            QMap<int, int> tally;
            for (auto it = weight[i].cbegin(); it != weight[i].cend(); ++it)
                tally[label[it.key()]] += it.value();
            int best = -1;
            int bestWeight = 0;
            for (auto it = tally.cbegin(); it != tally.cend(); ++it)
                if (it.value() > bestWeight) {
                    best = it.key();
                    bestWeight = it.value();
                }
            if (tally.value(label[i]) == bestWeight)
                best = label[i];
            if (best != label[i]) {
                label[i] = best;
                changed = true;
            }
        }
        if (!changed)
            break;
    }

    // Words shared by more than half of all instances (the robot's namespace, the project
    // prefix) do not tell subsystems apart.
    QHash<QString, int> everywhere;
    for (const NodeInstance *n : std::as_const(nodes))
        for (const QString &w : instanceWords(*n))
            ++everywhere[w];
    QMap<int, QList<int>> communities;
    for (int i = 0; i < count; ++i)
        if (!weight[i].isEmpty())
            communities[label[i]].append(i);
    QList<Group> out;
    QSet<QString> usedNames;
    for (const QList<int> &members : std::as_const(communities)) {
        if (members.size() < 2)
            continue;
        Group g;
        QHash<QString, int> tally;
        QSet<QString> names;
        for (int m : members) {
            g.memberIds << nodes[m]->id;
            for (const QString &w : instanceWords(*nodes[m]))
                ++tally[w];
            for (int other : members)
                for (const QString &s : shared[m].value(other))
                    names.insert(s);
        }
        QString best;
        int bestCount = 0;
        for (auto it = tally.cbegin(); it != tally.cend(); ++it) {
            const bool common = count >= 4 ? everywhere.value(it.key()) * 2 > count
                                           : everywhere.value(it.key()) == count;
            if (common)
                continue;
            if (it.value() > bestCount || (it.value() == bestCount && it.key() < best)) {
                best = it.key();
                bestCount = it.value();
            }
        }
        if (best.isEmpty())
            best = QStringLiteral("subsystem");
        QString name = best;
        for (int k = 2; usedNames.contains(name); ++k)
            name = best + QLatin1Char('_') + QString::number(k);
        usedNames.insert(name);
        g.name = name;
        g.sharedNames = QStringList(names.begin(), names.end());
        g.sharedNames.sort();
        out << g;
    }
    return out;
}

} // namespace rosarch
