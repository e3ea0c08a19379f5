#pragma once

#include "core/diagnostic.h"
#include "core/evidence.h"
#include "core/substitution.h"

#include <QList>
#include <QString>

namespace rosarch {

/// A remapping `from:=to` on a node or in scope (SetRemap / <remap>).
struct LaunchRemap
{
    Substitution from;
    Substitution to;
    Evidence evidence;
    bool operator==(const LaunchRemap &) const = default;
};

/// One parameter given to a node: a name and value, or a parameter file (`isFile`).
struct LaunchParameter
{
    Substitution name;  ///< empty for a parameter file
    Substitution value; ///< the value, or the file path
    bool isFile = false;
    Evidence evidence;
    bool operator==(const LaunchParameter &) const = default;
};

/// IfCondition / UnlessCondition / if= / unless=; `expression` is empty when there is none.
struct LaunchCondition
{
    Substitution expression;
    bool unless = false;
    QString text; ///< as written, for display
    bool isSet() const { return !text.isEmpty() || !expression.isEmpty(); }
    bool operator==(const LaunchCondition &) const = default;
};

/// One action of a launch description, as read from a launch file in any format. Readers
/// produce these trees; the LaunchAnalyzer executes them (scopes, arguments, includes).
struct LaunchAction
{
    enum class Kind
    {
        Node,                ///< Node / LifecycleNode / <node>
        ComposableContainer, ///< ComposableNodeContainer / <node_container>; children =
                             ///< ComposableNode
        ComposableNode,      ///< ComposableNode / <composable_node>
        LoadComposableNodes, ///< LoadComposableNodes(target_container=...); children =
                             ///< ComposableNode
        Include,             ///< IncludeLaunchDescription / <include>
        Group,               ///< GroupAction / <group>; children
        PushNamespace,       ///< PushRosNamespace / <push-ros-namespace>; `nameSpace`
        SetRemap,            ///< SetRemap / <remap> at scope level; remaps[0]
        DeclareArgument, ///< DeclareLaunchArgument / <arg>; `name`, `value` (default), `hasValue`
        SetLaunchConfiguration, ///< SetLaunchConfiguration / <let>; `name`, `value`
        SetParameter,           ///< SetParameter / <set_parameter>; parameters[0]
        Unresolved,             ///< OpaqueFunction, unknown action: `expression` says what
    };

    Kind kind = Kind::Node;
    Evidence evidence;
    LaunchCondition condition;

    // Node, ComposableNode, ComposableContainer
    Substitution package;
    Substitution executable;
    Substitution plugin;    ///< ComposableNode
    Substitution name;      ///< node name; argument / configuration name for DeclareArgument,
                            ///< SetLaunchConfiguration
    Substitution nameSpace; ///< node namespace; the pushed namespace for PushNamespace
    bool lifecycle = false;
    /// Node: its command-line arguments (`arguments=[...]`, `args="..."`), one per word; the
    /// `--ros-args` rules among them are also read into remaps and parameters.
    QList<Substitution> commandLine;
    QList<LaunchRemap> remaps;
    QList<LaunchParameter> parameters;

    // Group (children), ComposableContainer and LoadComposableNodes (composable children)
    QList<LaunchAction> children;
    bool scoped = true;  ///< Group: whether configurations and namespaces pop at its end
    Substitution target; ///< LoadComposableNodes: the container's name

    // Include: the file, and launch_arguments (name, value) in `arguments`
    Substitution path;
    QList<QPair<Substitution, Substitution>> arguments;

    // DeclareArgument, SetLaunchConfiguration
    Substitution value;
    bool hasValue = false;
    QString description;

    QString expression; ///< Unresolved: the expression text as written

    bool operator==(const LaunchAction &) const = default;
};

/// What a reader recovers from one launch file.
struct LaunchFileDescription
{
    enum class Format
    {
        Python,
        Xml,
        Yaml
    };

    QString file; ///< relative to the workspace root
    Format format = Format::Python;
    QList<LaunchAction> actions;
    QList<Diagnostic> diagnostics;
};

} // namespace rosarch
