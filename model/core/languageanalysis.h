#pragma once

#include "core/atomicnode.h"
#include "core/diagnostic.h"
#include "core/evidence.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A function that starts nodes (`main`, or any function a console script names): which
/// node classes it instantiates, so that build-file executables map to classes by evidence.
struct EntryPoint
{
    QString file;                          ///< relative to the workspace root
    QString function;                      ///< "main", ...
    QStringList instantiatedClasses;       ///< class names as written (possibly qualified)
    QList<NodeConstruction> constructions; ///< each construction of a node class, in order
    Evidence evidence;

    bool operator==(const EntryPoint &) const = default;
};

/// An `RCLCPP_COMPONENTS_REGISTER_NODE(ns::Class)` found in a source file.
struct ComponentRegistration
{
    QString file;
    QString pluginClass; ///< as written, e.g. "demo_nodes_cpp::Talker"
    Evidence evidence;

    bool operator==(const ComponentRegistration &) const = default;
};

/// What a language analyzer (Python or C++) recovers from the files it is given.
/// Nodes carry no id and no executables yet: the NodeAnalyzer stage links them to build files.
struct LanguageAnalysis
{
    QList<AtomicNode> nodes;
    QList<EntryPoint> entryPoints;
    QList<ComponentRegistration> registrations;
    QList<Diagnostic> diagnostics;
    /// Parameters that helper code (free functions, classes that are no nodes) declares on a
    /// node it is handed: which node is not followed, so the names are declared for any.
    QList<ParameterDeclaration> helperParameters = {};
};

} // namespace rosarch
