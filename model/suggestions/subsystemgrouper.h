#pragma once

#include "recovery.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Deterministic subsystem detection: the communication graph of the node instances a root
/// launch file starts (producer-consumer edges over resolved topic, service and action names,
/// hub topics left out), split by label propagation with sorted tie-breaking.
class SubsystemGrouper
{
public:
    /// A detected community of at least two instances.
    struct Group
    {
        QString name;            ///< the most common distinctive word of the members' names
        QStringList memberIds;   ///< node instance ids, in artifact order
        QStringList sharedNames; ///< "topic /robot1/scan", ... the names that bind them, sorted
    };

    explicit SubsystemGrouper(const Recovery &recovery);

    /// Topics that connect almost everything and say nothing about structure.
    static QStringList hubTopics();
    /// The runtime name of `name` (as written) for `instance`: remaps applied to the name as
    /// written, then relative and private names resolved against the instance's namespace.
    static QString resolveName(const QString &name, const NodeInstance &instance);
    /// The resolved names of an instance's ports, as "topic-out /x", "topic-in /x",
    /// "service-out /x", "service-in /x", "action-out /x", "action-in /x"; unresolved ports
    /// skipped.
    QStringList endpoints(const NodeInstance &instance) const;
    /// The groups among `instanceIds` (inactive instances are left out).
    QList<Group> groups(const QStringList &instanceIds) const;

private:
    const Recovery &m_recovery;
};

} // namespace rosarch
