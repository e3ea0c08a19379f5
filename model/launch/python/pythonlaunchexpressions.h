#pragma once

#include "launch/python/pythonlaunchcontext.h"

namespace rosarch::pylaunch {

class PythonLaunchBuiltins;
class PythonLaunchEvaluator;

/// Expression evaluation for the launch-file evaluator: names, literals, strings, containers,
/// operators, attributes, subscripts, comprehensions and call arguments, bounded in depth.
/// Calls themselves are the interpreter's.
class PythonLaunchExpressions
{
public:
    PythonLaunchExpressions(PythonLaunchContext &ctx, PythonLaunchEvaluator &interpreter,
                            PythonLaunchBuiltins &builtins);

    Value eval(TSNode node);
    /// The value of a name in the current frame's scopes (a module for an unknown import).
    Value lookup(TSNode identifier);
    /// The arguments of `call`, evaluated, with `*list` and `**dict` spread.
    CallArgs evalArguments(TSNode call);

private:
    Value evalNode(TSNode node);
    Value evalString(TSNode node);
    Value evalNumber(TSNode node);
    Value evalBinary(TSNode node);
    Value evalBoolean(TSNode node);
    Value evalComparison(TSNode node);
    Value evalSubscript(TSNode node);
    Value evalAttribute(TSNode node);
    Value evalComprehension(TSNode node);

    PythonLaunchContext &m_ctx;
    PythonLaunchEvaluator &m_interpreter;
    PythonLaunchBuiltins &m_builtins;
};

} // namespace rosarch::pylaunch
