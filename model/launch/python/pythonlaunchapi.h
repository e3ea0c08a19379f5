#pragma once

#include "core/launchaction.h"
#include "launch/python/pythonlaunchcontext.h"

#include <optional>

namespace rosarch::pylaunch {

class PythonLaunchEvaluator;

/// The launch API for the launch-file evaluator: calls of launch and launch_ros (Node,
/// ComposableNode, IncludeLaunchDescription, GroupAction, OpaqueFunction, ...) become
/// LaunchActions, substitution calls become Substitutions. An OpaqueFunction's body is run
/// by the interpreter.
class PythonLaunchApi
{
public:
    PythonLaunchApi(PythonLaunchContext &ctx, PythonLaunchEvaluator &interpreter);

    /// The launch action `name` (the last segment of the callee) built from `args`; none when
    /// `name` is no launch API call.
    std::optional<Value> callLaunchApi(const QString &name, const CallArgs &args, TSNode call);

private:
    std::optional<Value> callSubstitutionApi(const QString &name, const CallArgs &args,
                                             TSNode call);
    Value makeNode(const QString &name, const CallArgs &args, TSNode call);
    Value makeInclude(const CallArgs &args, TSNode call);
    Value makeOpaque(const QString &name, const CallArgs &args, TSNode call);
    void readNodeFields(LaunchAction &action, const CallArgs &args, const Evidence &evidence) const;
    QList<LaunchRemap> remaps(const Value &value, const Evidence &evidence) const;
    QList<LaunchParameter> parameters(const Value &value, const Evidence &evidence) const;
    LaunchCondition condition(const CallArgs &args) const;
    QString textOfCall(TSNode call) const;

    PythonLaunchContext &m_ctx;
    PythonLaunchEvaluator &m_interpreter;
};

} // namespace rosarch::pylaunch
