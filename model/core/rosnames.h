#pragma once

#include <QList>
#include <QPair>
#include <QString>

namespace rosarch::RosNames {

/// The namespace a launch file is analysed in on its own, for its classifier CCD (blueprint §1):
/// names under it are relative to the file's scope; `scopeRelative` takes it off again.
inline constexpr char kClassifierScope[] = "/__rosarch_file_scope__";

/// A name or namespace under kClassifierScope without it ("scan", "" for the scope itself);
/// other names unchanged.
QString scopeRelative(const QString &name);

/// A name that code joins to the parent of its node's namespace (navigation2's costmap layers,
/// `joinWithParentNamespace(topic)`): `{parent_namespace}/topic` until the instance is known.
inline constexpr char kParentNamespacePlaceholder[] = "{parent_namespace}";
/// A name per pluginlib plugin a node loads whose class derives from `Type`: navigation2's
/// costmap publishes each loaded CostmapLayer under the layer's name (`layer->getName()` in a
/// loop over its layers). `{plugin:Type}` until the instance's loaded plugins decide it.
inline constexpr char kLoadedPluginPrefix[] = "{plugin:";
/// `get_namespace()` in a node's code: the instance's namespace (`{namespace}/scan`); with
/// `get_name()` (`{node}`) it makes `get_fully_qualified_name()`.
inline constexpr char kNamespacePlaceholder[] = "{namespace}";
/// `name` with `{namespace}` replaced by namespace `ns` ("/" or "" for the root): never a
/// doubled slash (`{namespace}/x` in the root is `/x`).
QString withNamespace(const QString &name, const QString &ns);
/// `{parent_namespace}/map` in node namespace `/robot/global_costmap`: `/robot/map`; an absolute
/// name after the placeholder stays itself; any other name is returned as it is.
QString withParentNamespace(const QString &name, const QString &nodeNamespace);

/// The fully qualified node name: "/ns/node" ("/node" at the root).
QString fullyQualified(const QString &nameSpace, const QString &nodeName);

/// Expands a topic or service name as ROS 2 does for a node: absolute names stay, relative
/// names get the namespace, private names ("~", "~/x") get the node's fully qualified name.
QString expand(const QString &name, const QString &nameSpace, const QString &nodeName);

/// Applies the first remapping rule whose `from` expands to the same name as `name`; returns
/// the expanded result and the index of the rule used (-1 when none matched). Rules for the
/// node's own name or namespace (`__node`, `__ns`) and rules for another node ("n:from") are
/// skipped; a rule for this node ("<nodeName>:from") applies.
QString remap(const QString &name, const QList<QPair<QString, QString>> &rules,
              const QString &nameSpace, const QString &nodeName, int *ruleUsed = nullptr);

/// True when a remapping rule applies to topic and service names (not `__node`/`__ns`).
bool isNameRule(const QString &from);

/// A parameter value read as a boolean, as rclcpp/rclpy would: true/True/1 and false/False/0.
/// Returns false in `*known` when the value is not a boolean literal.
bool truthy(const QString &value, bool *known);

/// Evaluates a port guard as written ("use_x", "!use_x", "!(use_x)", "not self.use_x",
/// "mode_ == \"fast\"", "rate != 0") given the value of the parameter behind it; `*known` is
/// false when the guard is more than a single, possibly negated, variable or a comparison of
/// one with a literal, or when a boolean guard's value is not a boolean.
bool evaluateGuard(const QString &guard, const QString &parameterValue, bool *known);

} // namespace rosarch::RosNames
