#pragma once

#include "composition.h"

#include <QMap>
#include <QString>

namespace rosarch {

/// Writes ComposedClassifierDiagrams (blueprint §3) in PlantUML, deterministically: active
/// parts with their active ports, one package per namespace, bound topics, services and
/// actions, and the promoted boundary ports with their delegations. Parts of an accepted
/// subsystem (RosNodePart::subsystem) sit in a nested <<Subsystem>> component per namespace.
class CcdWriter
{
public:
    static QString write(const Composite &composite);
    /// File stem per representative composite (instance id -> stem): the launch stem,
    /// prefixed with the package where two launch files share it.
    static QMap<QString, QString> fileStems(const Architecture &arch);
};

} // namespace rosarch
