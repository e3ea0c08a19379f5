#pragma once

#include "core/atomicnodelist.h"
#include "workspace/workspace.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace rosarch {

/// Parameters that generate_parameter_library declares for a node (blueprint §1, "Parameters
/// of a class"): a package's CMakeLists.txt names a definition YAML per generated target, and
/// each node class of the package whose files include the generated header (`<target>.hpp`)
/// declares what the YAML defines: nested keys dotted, mapped keys (`__map_joints`) as
/// `{joints}`, types, defaults, descriptions, read-only, and `bounds<>` / `one_of<>` validators.
class GeneratedParameters
{
public:
    /// The definitions of one YAML file (workspace-relative `file`), in file order;
    /// problems become diagnostics.
    static QList<ParameterDeclaration> read(const QByteArray &content, const QString &file,
                                            QList<Diagnostic> *diagnostics);

    /// Adds the generated declarations to the node classes of every package that generates
    /// parameters.
    static void apply(const Workspace &workspace, AtomicNodeList *list);
};

} // namespace rosarch
