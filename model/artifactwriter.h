#pragma once

#include "atomicnodelist.h"

#include <QString>
#include <QStringList>

namespace rosarch {

/// Writes a run's artifacts into one folder with the fixed layout:
/// atomic_nodes.json, diagnostics.json, acd/<ClassName>.puml.
class ArtifactWriter
{
public:
    /// Returns false with a message when a file cannot be written; `written` lists the files.
    static bool writeAll(const AtomicNodeList &nodes, const QString &dir, QStringList *written,
                         QString *error);
};

} // namespace rosarch
