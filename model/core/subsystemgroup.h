#pragma once

#include <QString>
#include <QStringList>

namespace rosarch {

/// A named set of node instances an engineer accepted as one subsystem; drawn and exported
/// as a nested composite inside the composites that hold its members.
struct SubsystemGroup
{
    QString name;
    QStringList memberInstanceIds; ///< node instance ids ("n3", ...)
    QString rootId; ///< the root launch-file instance it applies below ("" = every root)
    bool operator==(const SubsystemGroup &) const = default;
};

} // namespace rosarch
