#pragma once

#include "core/atomicnode.h"
#include "core/atomicnodelist.h"

#include <QMap>
#include <QString>

namespace rosarch {

/// Writes AtomicClassifierDiagrams (blueprint §3) in PlantUML, deterministically.
class AcdWriter
{
public:
    static QString write(const AtomicNode &node);
    /// File stem per node id: the class name, prefixed with the package where two nodes share it.
    static QMap<QString, QString> fileStems(const AtomicNodeList &list);
};

} // namespace rosarch
