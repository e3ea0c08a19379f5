#pragma once

#include "core/atomicnodelist.h"
#include "core/launchaction.h"
#include "core/launchdependencies.h"
#include "launch/launchbudget.h"
#include "launch/modelledports.h"
#include "launch/nodeclasses.h"
#include "launch/xmlyaml/parameterfile.h"
#include "workspace/workspace.h"

#include <QHash>
#include <QMap>
#include <QSet>
#include <QString>
#include <QStringList>

#include <functional>

namespace rosarch {

/// Where an include points, once its path is evaluated.
struct IncludeTarget
{
    QString file;          ///< workspace-relative launch file ("" when not found)
    QString package;       ///< the package named by the path, if any
    bool external = false; ///< the package is not in the workspace
    QString shareRelative; ///< the path within the package's share folder, for a package
};

/// Executes launch descriptions symbolically, the way `ros2 launch` would walk them: launch
/// configurations, scoped groups, pushed namespaces and remaps, conditions, includes (with
/// cycle detection) and composable containers. Appends instances to a LaunchDependencies.
class LaunchExecutor
{
public:
    using Loader = std::function<const LaunchFileDescription *(const QString &file)>;

    /// A LoadComposableNodes whose container is none of the nodes made so far: the nodes it
    /// loaded (`first` to `end`, indices into the output's nodes) name it by `target`.
    struct UnfoundContainer
    {
        qsizetype first = 0;
        qsizetype end = 0;
        QString target;
        QString nameSpace; ///< of the scope the target was named in
    };

    LaunchExecutor(const Workspace &workspace, const AtomicNodeList &nodes, Loader loader,
                   LaunchDependencies *out);

    /// Runs `file` as a root with the given argument values; records declared arguments.
    /// `nameSpace` is the namespace the root runs in ("" for the system's root).
    void runRoot(const QString &file, const QMap<QString, QString> &arguments,
                 const QString &nameSpace = {});

    /// Prefixes the ids of the instances made ("c" gives "clf1", "cn1").
    void setIdPrefix(const QString &prefix) { m_idPrefix = prefix; }
    /// Appends to `out` from now on (a copy of an executor may run into another output).
    void setOutput(LaunchDependencies *out) { m_out = out; }
    /// Records each container a LoadComposableNodes does not find in `sink` (null: none).
    void setUnfoundContainers(QList<UnfoundContainer> *sink) { m_unfound = sink; }
    /// A namespace pushed onto itself (`/robot1/robot1`): a file pushes a namespace that an
    /// including file has pushed already, typically by both pushing it and passing it down as
    /// an argument. Found while running; the analyzer reports it once per site.
    struct DoubledNamespace
    {
        QString launchFileInstance; ///< the id of the instance whose action pushes again
        QString pushed;             ///< the namespace pushed again ("robot1")
        QString result;             ///< where its nodes run ("/robot1/robot1")
        Evidence evidence;          ///< the action that pushes again
        Evidence first;             ///< the including file's push
    };
    const QList<DoubledNamespace> &doubledNamespaces() const { return m_doubled; }
    /// The container a LoadComposableNodes in namespace `nameSpace` names by `target`, plain or
    /// fully qualified; the last node that matches() is the one. matches() is asked of every
    /// node made so far, for each load: it builds no name for a node whose name cannot match.
    class ContainerName
    {
    public:
        ContainerName(const QString &target, const QString &nameSpace);
        bool matches(const NodeInstance &n) const;

    private:
        QString m_target;
        QString m_scoped; ///< joinNamespace(nameSpace, target)
    };

    /// Evaluates an include path (as produced by SubstitutionEvaluator) to a launch file.
    IncludeTarget resolveInclude(const QString &path, const QString &fromFile) const;

    /// Every workspace launch file an include of `file` points to, without running them
    /// (defaults only); used to find the top-level launch files. `conditional`, when given,
    /// receives the files included under a condition that is false with the defaults (a file
    /// included that way is no entry point: some configuration of its includer starts it).
    QStringList directIncludes(const QString &file, QStringList *conditional = nullptr);

private:
    IncludeTarget findInclude(const QString &path, const QString &fromFile) const;

    struct Scope
    {
        QMap<QString, QString> configurations;
        /// Configurations whose value rests on something unresolved (an argument without a
        /// value, an expression beyond the evaluator): reading one reports it again, so the
        /// mark follows the value through `let`, arguments of includes and remaps.
        QSet<QString> guessed;
        QString nameSpace;             ///< "" = root
        bool guessedNamespace = false; ///< nameSpace rests on a guess (a pushed guessed value)
        Evidence namespacePush;        ///< the action that pushed the namespace's last part, if any
        QList<QPair<QString, QString>> remaps;
        QList<int> guessedRemaps;           ///< indices into remaps whose target is a guess
        QList<ParameterSetting> parameters; ///< SetParameter: source "launch"
        bool active = true;
        bool activeByGuess = false; ///< active only because a condition was undecidable
    };
    struct Frame
    {
        int instance = -1; ///< index into m_out->instances (-1 when collecting only)
        QString file;
        QStringList chain; ///< files from the root to here, for cycle detection
        bool root = false;
        bool collectOnly = false; ///< directIncludes(): no instances, no recursion
        QStringList *includes = nullptr;
        QStringList *conditionalIncludes = nullptr; ///< collecting: those under a false condition
    };

    void execute(const QList<LaunchAction> &actions, Scope &scope, Frame &frame, int depth);
    void executeNode(const LaunchAction &a, const Scope &scope, Frame &frame,
                     const QString &container);
    void executeInclude(const LaunchAction &a, Scope &scope, Frame &frame, int depth);
    /// The nodes an instance's class creates inside itself (blueprint §1, "Child nodes"), each
    /// an instance of its own in the same process, down to kMaxChildDepth generations.
    void addChildNodes(const NodeInstance &parent, const AtomicNode &cls, const LaunchAction &a,
                       const Scope &scope, const Frame &frame, int depth);
    static constexpr int kMaxChildDepth = 4;

    /// `guessed`, when given, tells whether the value rests on something unresolved.
    QString evaluate(const Substitution &s, const Scope &scope, const Frame &frame,
                     QList<Unresolved> *unresolved, const Evidence &evidence,
                     bool *guessed = nullptr) const;
    /// Evaluates remapping rules onto `remaps`, noting in `guessedRemaps` the index of each
    /// one whose target rests on a guess.
    void appendRemaps(const QList<LaunchRemap> &rules, const Scope &scope, const Frame &frame,
                      QList<Unresolved> *unresolved, QList<QPair<QString, QString>> *remaps,
                      QList<int> *guessedRemaps) const;
    /// Sets a configuration from an evaluated value, keeping whether it is a guess.
    static void configure(Scope &scope, const QString &name, const QString &value, bool guessed);
    bool conditionHolds(const LaunchAction &a, const Scope &scope, const Frame &frame,
                        QList<Unresolved> *unresolved, bool *undecided = nullptr) const;
    void addToNamespace(int instance, const QString &ns, const QString &id);
    /// Notes a DoubledNamespace when `pushed` (relative, decided) repeats the end of the scope's
    /// namespace that an action of another file pushed.
    void noteDoubledNamespace(const QString &pushed, bool guessed, const Scope &scope,
                              const Frame &frame, const Evidence &evidence);
    /// The parameters a node instance ends up with (blueprint §1): scope values, then the
    /// node's own values and parameter files in order, a later value over an earlier one; the
    /// declared defaults of the class's parameter-derived names and guards last.
    QList<ParameterSetting> effectiveParameters(const LaunchAction &a, const Scope &scope,
                                                const Frame &frame, const NodeInstance &n,
                                                const AtomicNode *cls, QList<Unresolved> *u);
    /// The plugins parameters name the pluginlib way: `FollowPath.plugin: "pkg::Class"` (or
    /// "pkg/Class") loads plugin FollowPath of that class, when another parameter names it
    /// (`controller_plugins: [FollowPath]`): a plugin no list names is not loaded.
    static QList<ParameterSetting> pluginsOf(const QList<ParameterSetting> &parameters);
    /// A parameter file given to a node (`--params-file`, RewrittenYaml), read once; null, with
    /// a diagnostic, when it is not in the workspace.
    const ParameterFile *parameterFile(const QString &path, const Frame &frame,
                                       const Evidence &evidence);

    const Workspace &m_workspace;
    Loader m_load;
    LaunchDependencies *m_out;
    NodeClasses m_classes;                  ///< which classes a launch action starts
    QHash<QString, QString> m_packagePaths; ///< package -> folder
    ModelledPorts m_modelled; ///< interface models of what comes from outside the workspace
    QHash<QString, QString> m_filePackages; ///< workspace file -> its package
    /// Classes by package + '\0' + executable, in stage 1's order; plugin classes by name
    /// (the first); the classes of each executable name, in order.
    /// resolveInclude's answers by path + '\0' + including file, and whether a path is a file:
    /// a stack includes the same files and parameter files from many places.
    mutable QHash<QString, IncludeTarget> m_includeTargets;
    mutable QHash<QString, bool> m_isFile;
    mutable LaunchBudget m_budget; ///< the sizes and counts one execution may reach
    QHash<QString, ParameterFile> m_parameterFiles; ///< by workspace-relative path
    QHash<QString, ParameterFile> m_rewrittenFiles; ///< RewrittenYaml results, by file and rewrites
    QSet<QString> m_missingParameterFiles;          ///< reported once per path
    QString m_idPrefix;
    QList<UnfoundContainer> *m_unfound = nullptr;
    QList<DoubledNamespace> m_doubled;
};

/// The folder of a workspace-relative launch file ("" at the top).
QString launchFileDir(const QString &file);
/// "python", "xml" or "yaml", as launch-file instances name their format.
QString formatName(LaunchFileDescription::Format f);

/// ROS 2 namespace rules: an absolute namespace stays, a relative one is appended.
QString joinNamespace(const QString &outer, const QString &inner);

} // namespace rosarch
