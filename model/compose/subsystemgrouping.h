#pragma once

#include "core/composition.h"
#include "core/subsystemgroup.h"

#include <QList>

namespace rosarch {

/// Puts accepted subsystem groups into an architecture: a pure step after stage 3, so the
/// composed model itself stays what the launch files say and groupings can be undone.
class SubsystemGrouping
{
public:
    /// A copy of `architecture` where every node part whose instance is a member of a group
    /// (in a composite below the group's root) has `subsystem` set to the group's name. A part
    /// claimed by several groups keeps the first; parts already grouped are left as they are.
    static Architecture apply(const Architecture &architecture,
                              const QList<SubsystemGroup> &groups);
    /// The root launch-file instance above `instanceId` (itself for a root; "" when unknown).
    static QString rootOf(const Architecture &architecture, const QString &instanceId);
};

} // namespace rosarch
