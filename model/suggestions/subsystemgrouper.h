#pragma once

#include "pipeline/recovery.h"

#include <QHash>
#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Deterministic subsystem detection: the communication graph of the node instances a root
/// launch file starts (producer-consumer edges over the topic, service and action names stage 3
/// resolved, hub topics left out), split by label propagation with sorted tie-breaking.
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
    /// The names stage 3 resolved for an instance's ports (namespaces, remaps, parameter
    /// values), as "topic-out /x", "topic-in /x", "service-out /x", "service-in /x",
    /// "action-out /x", "action-in /x"; unresolved and inactive ports skipped.
    QStringList endpoints(const NodeInstance &instance) const;
    /// The groups among `instanceIds` (inactive instances are left out).
    QList<Group> groups(const QStringList &instanceIds) const;

private:
    const Recovery &m_recovery;
    QHash<QString, const RosNodePart *> m_parts; ///< node instance id -> its part in stage 3
};

} // namespace rosarch
