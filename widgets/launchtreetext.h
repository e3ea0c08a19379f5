#pragma once

#include "core/launchdependencies.h"

#include <QCoreApplication>
#include <QString>

namespace rosarch {

struct AtomicNode;

/// The words the launch tree shows: executable, details and tooltips that say what an
/// instance is, what it was given and where it comes from (file:line).
class LaunchTreeText
{
    Q_DECLARE_TR_FUNCTIONS(rosarch::LaunchTreeText)
public:
    /// "py_talker/talker", or the plugin of a composable node.
    static QString nodeExecutable(const NodeInstance &node);
    /// "/robot1/talker": the fully qualified node name.
    static QString fullyQualifiedName(const NodeInstance &node);
    /// "if: $(var use_echo) · remap: chatter→speech · param: rate=2.0"
    static QString nodeDetails(const NodeInstance &node, int composableCount);
    /// "py_talker · 2 nodes · 1 include · robot:=robot1"
    static QString launchFileDetails(const LaunchFileInstance &instance);
    /// "unresolved substitution · guess: robot1"
    static QString unresolvedDetails(const Unresolved &unresolved);

    /// `atomicNode` is the class the instance resolves to (null when unknown);
    /// `inWorkspace` whether the node's package is one of the workspace's.
    static QString nodeToolTip(const NodeInstance &node, const AtomicNode *atomicNode,
                               bool inWorkspace, bool parentActive);
    static QString launchFileToolTip(const LaunchFileInstance &instance,
                                     const QList<Unresolved> &attributeUnresolved,
                                     bool parentActive);
    static QString namespaceToolTip(const QString &nameSpace, const LaunchFileInstance &instance,
                                    int itemCount);
    static QString unresolvedToolTip(const Unresolved &unresolved);
    /// "0.5 · nav2_params.yaml:184", "odom · default in code", "true · launch file:12"
    static QString parameterDetails(const ParameterSetting &parameter);
    static QString parameterToolTip(const ParameterSetting &parameter);

    /// "substitution", "condition", ... for people.
    static QString unresolvedKindLabel(const QString &kind);
};

} // namespace rosarch
