#pragma once

#include "core/composition.h"

#include <QList>
#include <QString>

namespace rosarch {

/// A port of a node instance that talks on a topic, service or action.
struct Talker
{
    QString instanceId;  ///< the node instance ("n3")
    QString compositeId; ///< the composite that draws its part
    QString partId;      ///< its part there ("part2")
    QString nodeName;    ///< fully qualified: "/front/detector"
    QString className;   ///< the ARC's class name (exec name when unknown)
    QString classId;     ///< the ARC id ("" when unknown)
    bool active = true;  ///< the launch condition and the port's guard hold
    PartPort port;
};

/// Everyone on one resolved name: "topic" /scan, its type, publishers and subscribers (or
/// servers and clients), providers first.
struct TalkerGroup
{
    QString family; ///< "topic", "service" or "action" (portFamilyName)
    QString name;   ///< resolved absolute name
    QString type;   ///< the first type seen
    QList<Talker> talkers;
    qsizetype providers() const; ///< publishers, service or action servers
};

/// Who talks on a name inside a composite and the composites it includes: a pure search of
/// the composed architecture for the talkers panel.
class TalkerSearch
{
public:
    /// The ports of node instances in `compositeId` (and everything it includes) of `family`
    /// named `name`: providers first, then by node name and port id.
    static TalkerGroup find(const Architecture &architecture, const QString &compositeId,
                            const QString &family, const QString &name);
    /// The names the port `portId` of the class `classId` resolves to for its instances in
    /// `compositeId` (and below), each with its talkers, sorted by name.
    static QList<TalkerGroup> ofClassPort(const Architecture &architecture,
                                          const QString &compositeId, const QString &classId,
                                          const QString &portId);
    /// The port's group: the talkers on what the port of `partId` in `compositeId` talks on.
    static TalkerGroup ofPartPort(const Architecture &architecture, const QString &compositeId,
                                  const QString &partId, const QString &portId);
    /// The nearest composite, `compositeId` or else a root, that starts an instance of `classId`
    /// ("" when none does).
    static QString scopeOfClass(const Architecture &architecture, const QString &compositeId,
                                const QString &classId);
};

} // namespace rosarch
