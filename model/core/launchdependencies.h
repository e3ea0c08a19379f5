#pragma once

#include "core/diagnostic.h"
#include "core/evidence.h"
#include "core/port.h"
#include "core/provenance.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// Something the analysis could not decide statically, kept on the element it concerns.
struct Unresolved
{
    QString kind; ///< "substitution", "condition", "include", "opaque-function", "argument", ...
    QString expression; ///< as written
    QString guess;      ///< the default or best guess used for the rest of the analysis
    Evidence evidence;
    bool operator==(const Unresolved &) const = default;
};

/// A parameter's final value for a node instance, and where it comes from (blueprint §1:
/// launch values over parameter files, later sources over earlier ones, the code default last).
struct ParameterSetting
{
    QString name;      ///< dotted, as rclcpp names it ("FollowPath.max_vel_x")
    QString value;     ///< as text; lists as "[a, b]"
    QString source;    ///< "launch" (a value in the launch file), "file" (a parameter file) or
                       ///< "default" (the declared default in code)
    QString file;      ///< the parameter file (workspace-relative) for source "file"
    Evidence evidence; ///< the YAML line, the launch line, or the declaration in code
    /// The value's type as ROS reads it (parameterValueType); "" when open
    QString type = {};
    bool wildcard = false; ///< from a parameter file's key for many nodes (`/**`, `/*/x`)
    bool operator==(const ParameterSetting &) const = default;
};

/// A node instance started by a launch file (blueprint §2 list_atom_node_instances).
struct NodeInstance
{
    QString id;           ///< "n1", ...
    QString launchFileId; ///< the launch-file instance that declares it
    QString nodeKind;     ///< "python", "cpp" or "composable" ("" when the class is unknown)
    QString package;
    QString execName;  ///< executable, or plugin for a composable node
    QString className; ///< the ARC it resolves to ("" when not found in the workspace)
    QString classId;   ///< that ARC's id in the List of Atomic ROS Nodes
    QString nodeName;  ///< runtime name: from the launch file, else the name in code
    QString nameSpace; ///< effective namespace ("/" at the root)
    /// The namespace, or the launch file's node name, rests on a guessed launch value (an
    /// argument nobody sets): the names built from it are guesses too.
    bool guessedNamespace = false;
    bool guessedName = false;
    /// The launch action named it (`name=`, `<node name=...>`): with an executable that builds
    /// several nodes, every one of them gets that name.
    bool namedByLaunch = false;
    QString container; ///< composable: the container instance id (or its name when not found)
    bool lifecycle = false;
    QList<QPair<QString, QString>> remaps; ///< evaluated from -> to (scope remaps first)
    QList<int> guessedRemaps; ///< indices into remaps whose target rests on a guess (unresolved)
    QList<QPair<QString, QString>> parameters;   ///< name -> value; parameter files as ("", path)
    QList<ParameterSetting> effectiveParameters; ///< the final values, one per name, sorted
    /// The plugins the instance loads, named by its parameters the pluginlib way
    /// (`<name>.plugin: pkg::Class`): name -> class; each entry's evidence is its parameter's.
    QList<ParameterSetting> plugins;
    QString condition;  ///< as written ("" when none)
    bool active = true; ///< the condition's value (true when undecidable: best guess)
    /// Active only by that best guess: its condition, or a group's or include's around it,
    /// could not be decided, so it may be one of alternatives that never run together.
    bool activeByGuess = false;
    QList<Unresolved> unresolved;
    Evidence evidence;
    /// A person's corrections of this instance (blueprint §5), applied by stage 3: ports added
    /// (absolute names) and port ids removed.
    QList<Port> addedPorts = {};
    QStringList removedPorts = {};
    Marks marks = {}; ///< provenance and review (blueprint §5); set by the corrected model
    /// An executable outside the workspace described by an interface model (blueprint §1):
    /// the model's name and its ports, which cite this launch action as their evidence.
    QString interfaceModel = {};
    QList<Port> modelledPorts = {};
    QString modelConfig = {}; ///< the configuration file the model read more ports from
    /// A child node (blueprint §1): the instance whose node created it ("" for a launched node).
    QString parentNode = {};
    /// A node an executable's code constructs (blueprint §1, "Nodes built in code"): the
    /// class's ports its constructor arguments name, by port id, in place of the class's.
    QList<Port> constructedPorts = {};
    bool operator==(const NodeInstance &) const = default;
};

/// A group (GroupAction / <group>) with a condition, as a launch run met it.
struct LaunchGroupCondition
{
    QString condition;      ///< as written
    bool unless = false;    ///< UnlessCondition / unless=
    bool holds = true;      ///< the condition's value (true when undecidable: best guess)
    bool undecided = false; ///< it could not be decided: the group runs as the best guess
    Evidence evidence;      ///< the group
    bool operator==(const LaunchGroupCondition &) const = default;
};

/// A launch-file instance: a root, or one include of a file (a file included twice gives two).
struct LaunchFileInstance
{
    QString id;                            ///< "lf1", ...
    QString type;                          ///< the launch file name, e.g. "bringup.launch.py"
    QString file;                          ///< relative to the workspace root ("" when external)
    QString package;                       ///< the package that contains (or would contain) it
    QString format;                        ///< "python", "xml", "yaml"
    QString parentId;                      ///< the including instance ("" for a root)
    bool external = false;                 ///< an include of a package that is not in the workspace
    QStringList nodes;                     ///< node instance ids it declares directly
    QStringList includedLaunchFiles;       ///< launch-file instance ids it includes directly
    QMap<QString, QStringList> namespaces; ///< namespace scope -> ids of instances inside it
    QList<QPair<QString, QString>> arguments; ///< effective launch arguments (declared or passed)
    QString condition;
    bool active = true;
    QList<Unresolved> unresolved;
    Evidence evidence; ///< the include (or the file itself for a root)
    /// An external launch file described by an interface model: its name and the ports of the
    /// nodes it starts, with `modelNamespace` (the includer's scope and the model's namespace
    /// argument) applied to their relative names.
    QString interfaceModel = {};
    QList<Port> modelledPorts = {};
    QString modelNamespace = {};
    /// The file's groups that have a condition, in the order the run met them.
    QList<LaunchGroupCondition> groups = {};
    bool operator==(const LaunchFileInstance &) const = default;
};

/// A launch argument a root launch file declares, with its default and the user's value.
struct LaunchArgument
{
    QString name;
    QString defaultValue;
    bool hasDefault = false;
    QString description;
    QString launchFile; ///< where it is declared
    Evidence evidence;
    bool operator==(const LaunchArgument &) const = default;
};

/// A port whose counterpart is expected outside the workspace (blueprint §1, "Expected
/// external inputs and outputs"): a driver, teleoperation, a bag, a tool. Declared in the
/// project; such a port is no finding.
struct ExpectedExternal
{
    /// A fully qualified topic, service or action name, or a pattern of one with `*` (within a
    /// segment) and `**` (any segments), as parameter files write node names.
    QString name;
    /// True: something outside reads it (an output); false: something outside provides it (a
    /// topic the system subscribes to, a service or action it calls).
    bool output = false;
    QString reason; ///< why, as the person said it
    bool operator==(const ExpectedExternal &) const = default;
};

/// Stage 2's result: the Launch File Dependency Description.
struct LaunchDependencies
{
    QStringList launchFiles; ///< every launch file found (workspace-relative), sorted
    QList<LaunchFileInstance>
        instances; ///< roots first, each followed by its includes (depth first)
    QList<NodeInstance> nodes;
    QList<LaunchArgument> arguments; ///< declared by the analysed roots
    /// The systems the architecture checks judge (blueprint §1, "Checks run on entry points"):
    /// the launch files no other file includes under any condition, or the chosen root.
    /// Workspace-relative, sorted.
    QStringList entryPoints;
    /// The topics the workspace's RViz configurations display (subscribers, by name as
    /// written, with the configuration's line): outputs that exist to be viewed.
    QList<Port> viewedTopics;
    /// The ports the project expects to meet something outside the workspace (from the
    /// analysis options): the checks do not report them.
    QList<ExpectedExternal> externals;
    /// Each launch file analysed on its own with its declared defaults, in the classifier scope
    /// (RosNames::kClassifierScope), for its CCD: the runs' launch-file instances ("clf1", ...)
    /// and node instances ("cn1", ...). Not part of the system; not in the JSON.
    QList<LaunchFileInstance> classifierInstances;
    QList<NodeInstance> classifierNodes;
    QList<Diagnostic> diagnostics;
    bool canceled = false;

    const LaunchFileInstance *instance(const QString &id) const;
    const NodeInstance *node(const QString &id) const;
    bool operator==(const LaunchDependencies &) const = default;
};

} // namespace rosarch
