#pragma once

#include "core/evidence.h"

#include <QList>
#include <QString>
#include <QStringList>

namespace rosarch {

/// A parameter a node class (or a plugin) declares (blueprint §1, "Parameters of a class").
struct ParameterDeclaration
{
    /// The name as rclcpp names it: dotted, with `{plugin}` where the plugin's instance name
    /// goes, and `{expression}` around any other part the code decides at run time.
    QString name;
    QString nameExpression; ///< the name as written when it is not a literal ("" otherwise)
    /// "bool", "integer", "double", "string", "byte_array", "bool_array", "integer_array",
    /// "double_array", "string_array"; "" when the declaration does not fix it
    QString type;
    QString defaultValue; ///< as text (lists "[a, b]"); "" when hasDefault is false
    bool hasDefault = false;
    bool readOnly = false;
    bool dynamicTyping = false; ///< its descriptor allows any type
    QString description;
    QString range; ///< "[from, to]", "[from, to] step s", or "one of [a, b]"
    QString guard; ///< the condition in code it is declared under ("" = always)
    QString via;   ///< the call or file that declares it ("declare_parameter", ...)
    /// declared by a base class of the node, or by helper code it runs with itself (a helper
    /// class it constructs, a free function it calls)
    bool inherited = false;
    Evidence evidence;
    bool operator==(const ParameterDeclaration &) const = default;
};

/// The ROS parameter type a value written in a parameter file or a launch file has, as
/// rclcpp reads it: "bool", "integer", "double", "string" or an array of one of them ("" for
/// an empty list, whose element type is open).
QString parameterValueType(const QString &text, bool quoted = false);

/// Whether a value of type `given` can be set on a parameter declared with type `declared`
/// (statically typed, as rclcpp and rclpy check it).
bool parameterTypeAccepts(const QString &declared, const QString &given);

/// The ROS parameter type of a C++ or Python type as written (`double`, `std::string`,
/// `std::vector<int64_t>`, `PARAMETER_DOUBLE`, `float`, `List[str]`); "" when unknown.
QString parameterTypeOfWritten(const QString &written);

/// Whether a parameter `key` given to an instance is the declared `name` once `plugin`
/// fills its `{plugin}` part; other `{...}` parts match any text.
bool parameterNameMatches(const QString &name, const QString &key);

/// `name` with its `{plugin}` part filled in.
QString parameterNameFor(const QString &name, const QString &plugin);

/// Whether the declared name has parts decided at run time other than the plugin's name.
bool parameterNameIsPattern(const QString &name);

/// Parameters every node accepts without declaring them (`use_sim_time`, QoS overrides, ...).
bool isBuiltinParameter(const QString &key);

} // namespace rosarch
