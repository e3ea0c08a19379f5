#pragma once

#include <QList>
#include <QString>

namespace rosarch {

/// A launch-time value as written in a Python, XML or YAML launch file, kept symbolic so that
/// it can be evaluated later against launch arguments (ROS 2 launch "substitutions").
struct Substitution
{
    enum class Kind
    {
        Text,                ///< literal text
        LaunchConfiguration, ///< LaunchConfiguration('x') / $(var x); `text` = name, parts[0] =
                             ///< default if any
        EnvironmentVariable, ///< EnvironmentVariable('X') / $(env X [default]); `text` = name,
                             ///< parts[0] = default
        FindPackageShare,    ///< FindPackageShare('p') / get_package_share_directory /
                             ///< $(find-pkg-share p); parts[0] = package
        FindPackagePrefix,   ///< FindPackagePrefix / $(find-pkg-prefix p); parts[0] = package
        PathJoin,            ///< PathJoinSubstitution / os.path.join: parts joined with '/'
        Concat,              ///< a list of substitutions, an f-string, '+' of strings
        Eval, ///< PythonExpression / $(eval ...): parts concatenated, then evaluated if simple
        ThisLaunchFileDir, ///< ThisLaunchFileDir() / $(dirname)
        ThisLaunchFile,    ///< ThisLaunchFile() / $(filename)
        RewrittenYaml,     ///< nav2_common's RewrittenYaml: parts[0] = source file, parts[1] = root
                           ///< key, then each rewrite as a name and a value (a value
                           ///< rewrite's name starts with '='); evaluates to the file
        Unknown, ///< anything else (Command, OpaqueFunction results, ...): `text` = the expression
        /// A launch function of its arguments, evaluated as ROS 2 launch does: `text` = "equals",
        /// "not-equals", "and", "or", "not", "all", "any" or "if"; parts = the arguments
        /// (EqualsSubstitution / $(equals a b), IfElseSubstitution / $(if c a b), ...).
        Function,
    };

    Kind kind = Kind::Text;
    QString text;
    QList<Substitution> parts;

    static Substitution literal(const QString &text);
    static Substitution unknown(const QString &expression);
    static Substitution configuration(const QString &name);
    static Substitution concat(QList<Substitution> parts);
    static Substitution function(const QString &name, QList<Substitution> arguments);

    bool isEmpty() const { return kind == Kind::Text && text.isEmpty(); }
    bool isLiteral() const { return kind == Kind::Text; }
    /// Whether it finds a package's share (or prefix) whose package name comes from a launch
    /// configuration: `$(find-pkg-share $(var pkg))/...` names a file of several packages.
    bool findsPackageByConfiguration(int depth = 0) const;
    /// A readable form for diagnostics and tooltips, e.g. "$(var ns)/robot".
    QString describe() const;
    bool operator==(const Substitution &) const = default;
};

} // namespace rosarch
