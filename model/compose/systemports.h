#pragma once

#include "core/composition.h"

#include <QHash>
#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// One active port of a node part in a system.
struct PortUse
{
    const RosNodePart *part;
    const PartPort *port;
};

/// Everyone on one topic, service or action of a system.
struct PortFamily
{
    QList<PortUse> providers; ///< publishers, servers
    QList<PortUse> users;     ///< subscribers, clients
};

/// The ports of one system (an entry point and everything it starts) by family and resolved
/// name ("topic /scan", "service /map"), in the order they were met, and the lookups the
/// architecture checks make across names (a likely misspelling on the other side). A port whose
/// name is not resolved, or rests on a guess, is left out: it proves nothing about who hears whom.
class SystemPorts
{
public:
    void clear();
    void add(const RosNodePart &part);

    const QStringList &keys() const { return m_order; }
    PortFamily family(const QString &key) const { return m_families.value(key); }

    /// A name of the family that `name` looks like a misspelling of, among those with a
    /// provider when `wantProviders`, else among those with users, with its first port of a
    /// part other than `except`; nullptr when there is none. A misspelling differs in one
    /// segment by one letter that is no digit (`/whel_odom`, `/wheel_odom`): names that differ
    /// more, or by a number, are as often siblings by design (`/robot1/scan` and
    /// `/robot2/scan`, `camera6` and `camera7`, `local_costmap` and `global_costmap`).
    const PortUse *misspelling(const QString &family, const QString &name, bool wantProviders,
                               const RosNodePart *except, QString *found) const;

    /// A name of the family that is `name` in another namespace: one in a namespace nested in
    /// the other's (`/goal_pose` and `/robot1/goal_pose`, `/robot1/battery_state` and
    /// `/robot1/monitoring/battery_state`), or one with its namespace doubled (`/robot1/cmd_vel`
    /// and `/robot1/robot1/cmd_vel`), where at least one of the two is written relative and
    /// not remapped, so that a namespace put it there; open as `name` is (providers when
    /// `wantProviders`, and nobody on their other side), of the same type as `use` (known on both),
    /// of a part other than `use`'s; nullptr when there is none. A namespace pushed once too often
    /// or not at all leaves such pairs.
    const PortUse *namespaceSlip(const QString &family, const QString &name, const PortUse &use,
                                 bool wantProviders, QString *found) const;

    /// misspelling() stopped looking: its work budget for the run is spent.
    bool hintsCut() const { return m_hintWork > kHintBudget; }
    static constexpr qint64 kHintBudget = 50'000'000;

private:
    QHash<QString, PortFamily> m_families;
    QStringList m_order;
    QHash<QString, QStringList> m_byLastSegment; ///< "topic scan" -> the keys ending so
    QHash<QString, QStringList> m_byLength;      ///< "topic 5" -> the keys of names that long
    /// Work done by misspelling() in this run (names looked at and letters compared): past a
    /// budget it stops looking, so that it stays linear however many systems and names there
    /// are.
    mutable qint64 m_hintWork = 0;
};

} // namespace rosarch
