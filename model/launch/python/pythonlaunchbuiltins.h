#pragma once

#include "launch/python/pythonlaunchcontext.h"

#include <optional>

namespace rosarch::pylaunch {

/// Builtins and methods of plain Python values for the launch-file evaluator: str, list, dict,
/// os.path, os.environ, range, format strings; unknown where the answer depends on runtime.
class PythonLaunchBuiltins
{
public:
    explicit PythonLaunchBuiltins(PythonLaunchContext &ctx);

    /// The builtin or library function `dotted` ("len", "os.path.join") called with `args`;
    /// none when it is not one of them.
    std::optional<Value> callBuiltin(const QString &dotted, const CallArgs &args, TSNode call);
    /// `object.method(args)`.
    Value callMethod(const Value &object, const QString &method, const CallArgs &args, TSNode call);
    /// `format % values` (`percent`) or `format.format(...)` / an f-string's parts.
    Value formatString(const QString &format, const QList<Value> &positional,
                       const QList<QPair<QString, Value>> &keywords, bool percent, TSNode node);

private:
    PythonLaunchContext &m_ctx;
};

} // namespace rosarch::pylaunch
