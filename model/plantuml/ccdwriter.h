#pragma once

#include "core/composition.h"

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
    /// An element of the composite and the line declaring it in the written text.
    struct WrittenElement
    {
        enum class Kind
        {
            Part,
            Channel,
            Boundary,
            Connection
        };
        int line = 0; ///< 1-based
        Kind kind = Kind::Part;
        QString id; ///< part, channel or boundary port id; a connection's index
    };

    /// The CCD of `composite`; with `elements`, also where each element was written.
    static QString write(const Composite &composite, QList<WrittenElement> *elements = nullptr);
    /// File stem per representative composite (instance id -> stem): the launch stem,
    /// prefixed with the package where two launch files share it.
    static QMap<QString, QString> fileStems(const Architecture &arch);
};

} // namespace rosarch
