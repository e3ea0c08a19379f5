#pragma once

#include "core/port.h"

#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A person's edit of the recovered model (blueprint §5). It names its target by stable key
/// and records what the target said before, so that it can be shown, reverted, and listed as
/// orphaned when the target is gone.
struct Correction
{
    enum class Kind
    {
        Rename,        ///< a node instance (its name), a port's name, or a topic/service/action
        SetName,       ///< the name of a port analysis left as an expression
        SetType,       ///< the type of a port analysis left unknown (`?`)
        Remove,        ///< a node instance, a class, a port, or one instance's port (connection)
        AddPort,       ///< a port of a class
        AddPart,       ///< a node instance declared in a launch file
        AddConnection, ///< a port of one node instance on a topic, service or action
        Group,         ///< node instances as a subsystem under a root launch file
        Review,        ///< an element marked as reviewed
        Describe       ///< the description of a class
    };

    QString id; ///< "c1", ... unique in the project, never reused
    Kind kind = Kind::Rename;
    /// The element's stable key: `class:`, `port:`, `instance:`, `part:`, `include:` (Group: the
    /// root), `launch:` (AddPart), `topic:`/`service:`/`action:`.
    QString target;
    QString oldValue; ///< what the element said before ("" for an addition)
    QString newValue; ///< the new name, type, or group name; a node name for AddPart
    /// Remove or AddConnection on one instance: the port key (Remove) or "" (AddConnection).
    QString port;
    PortKind portKind = PortKind::Publisher; ///< AddPort, AddConnection
    QString type;                            ///< AddPort, AddConnection: the interface type
    QString classKey;                        ///< AddPart: the class it instantiates
    QString nameSpace;                       ///< AddPart
    QStringList members;                     ///< Group: instance keys
    QString reason;
    QString author;
    QDateTime time; ///< UTC

    bool operator==(const Correction &) const = default;

    /// "rename", "set-name", "set-type", "remove", "add-port", "add-part", "add-connection",
    /// "group", "review", "describe".
    static QString kindName(Kind kind);
    static bool kindFromName(const QString &name, Kind *kind);
    /// A one-line account for lists: "Rename /scan → /laser".
    QString summary() const;

    QJsonObject toJson() const;
    /// False (with `error`) when `o` is not a correction.
    static bool fromJson(const QJsonObject &o, Correction *correction, QString *error);
};

} // namespace rosarch
