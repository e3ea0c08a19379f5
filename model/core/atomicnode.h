#pragma once

#include "core/evidence.h"
#include "core/parameter.h"
#include "core/port.h"
#include "core/provenance.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A node that a node creates inside itself (blueprint §1, "Child nodes"): nav2's
/// `Costmap2DROS` made by the planner server, a member node built with a name.
struct ChildNode
{
    QString className; ///< the child's class, qualified as in the List of Atomic ROS Nodes
    QString nodeName;  ///< its node name ("" when the construction does not decide it)
    /// Its namespace relative to the parent's ("" = the parent's own namespace); absolute
    /// when the construction names an absolute one.
    QString nameSpace;
    Evidence evidence; ///< the construction
    bool operator==(const ChildNode &) const = default;
};

/// A node object that an executable's own code constructs (blueprint §1, "Nodes built in
/// code"), with what its constructor arguments decide.
struct NodeConstruction
{
    QString className;  ///< the class as written at the construction
    QString executable; ///< the executable whose code builds it (set when stage 1 links it)
    QString nodeName;   ///< "" when the arguments do not decide it (the class's name then)
    /// The `if` conditions the construction is under, as written ("" = always): constructions
    /// in two branches are alternatives that may never run together.
    QString guard;
    /// The class's ports that the arguments name (`create_publisher<T>(output, ...)`, `output`
    /// a constructor parameter), with the class port's id; the others are the class's.
    QList<Port> ports;
    Evidence evidence; ///< the construction
    bool operator==(const NodeConstruction &) const = default;
};

/// An AtomicRosNodeClassifier: one node class (or procedurally built node) with its ports.
struct AtomicNode
{
    enum class CompileType
    {
        Python,
        Cpp
    };

    QString id;        ///< "arc_1", ... assigned in deterministic order by the stage
    QString className; ///< unqualified class name; for procedural nodes the function's file stem
    QString qualifiedName; ///< with C++ namespaces ("demo_nodes_cpp::Talker") or Python module path
    QString nodeName;      ///< as written in the code ("" when not given)
    QString packageName;
    QStringList headerFiles; ///< relative to the workspace root
    QStringList sourceFiles;
    QString description;
    CompileType compileType = CompileType::Cpp;
    QStringList baseClasses; ///< direct bases as written
    bool lifecycle = false;
    bool procedural = false; ///< rclpy.create_node / make_shared<rclcpp::Node>(...)
    QStringList executables; ///< executables that start it (from build files)
    QStringList plugins;     ///< component plugin names (rclcpp_components)
    /// A pluginlib plugin (kind "plugin"): the interface it is exported as ("" for a node).
    QString pluginInterface;
    Evidence evidence; ///< the class definition (or the create_node call)
    QList<Port> ports;
    QList<ChildNode> children = {}; ///< nodes it creates inside itself
    /// Where executables' own code constructs it, one per construction (several instances of
    /// one class each get theirs)
    QList<NodeConstruction> constructions = {};
    QList<ParameterDeclaration> parameters = {}; ///< declared parameters, in source order
    /// It takes any parameter (`allow_undeclared_parameters`,
    /// `automatically_declare_parameters_from_overrides`): none given to it is undeclared.
    bool acceptsUndeclared = false;

    Marks marks = {}; ///< provenance and review (blueprint §5); set by the corrected model
    /// The blueprint's `execution`: the first executable, else the first plugin.
    QString execution() const;
    bool isComposable() const { return !plugins.isEmpty(); }
    bool isPlugin() const { return !pluginInterface.isEmpty(); }
    bool operator==(const AtomicNode &) const = default;
};

QString compileTypeName(AtomicNode::CompileType type);

} // namespace rosarch
