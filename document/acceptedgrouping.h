#pragma once

#include <QString>
#include <QStringList>

namespace rosarch {

/// A subsystem grouping a person accepted: a named set of node instances below a root
/// launch file, to be drawn and exported as a nested composite.
struct AcceptedGrouping
{
    QString name;
    QStringList memberIds; ///< node instance ids, sorted
    QString rootId;        ///< the root launch-file instance id
    bool operator==(const AcceptedGrouping &) const = default;
};

} // namespace rosarch
