#pragma once

#include "diff/architecturesnapshot.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace rosarch {

/// One difference between two recoveries.
struct ArchitectureChange
{
    enum class Kind
    {
        Added,
        Removed,
        Changed, ///< same element, another type
        Renamed  ///< same element (same kind, type and neighbours), another name
    };
    Kind kind = Kind::Added;
    QString element; ///< "node class", "port", "launch file", "part", "topic", "service",
                     ///< "action", "connection"
    QString scope;   ///< the node class (for a port) or the launch file (for what a CCD holds)
    QString before;  ///< "" when added
    QString after;   ///< "" when removed
    bool operator==(const ArchitectureChange &) const = default;

    static QString kindName(Kind kind); ///< "added", "removed", "changed", "renamed"
    /// One line: "renamed topic /chatter -> /chat (in launch/demo.launch.py)".
    QString describe() const;
};

/// What changed from `before` to `after`. A topic, service or action whose name changed but
/// whose kind, type and connections did not is one rename (its connections do not show as
/// removed and added); so is a port of a class that changed only its name.
class ArchitectureDiff
{
public:
    static QList<ArchitectureChange> compare(const ArchitectureSnapshot &before,
                                             const ArchitectureSnapshot &after);
    /// A summary line and one line per change, grouped by scope.
    static QString text(const QList<ArchitectureChange> &changes);
    /// {"version": 1, "summary": {added, removed, changed, renamed}, "changes": [...]}.
    static QByteArray json(const QList<ArchitectureChange> &changes);
};

} // namespace rosarch
