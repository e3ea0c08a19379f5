#pragma once

#include <QString>

namespace rosarch {

/// What launch's `$(eval ...)` and PythonExpression compute once their substitutions are text:
/// the expression, run by the Python launch-file evaluator, so that a launch file of any format
/// reads Python alike. Only a value the evaluator knows exactly counts: no name it cannot bind,
/// no guess between alternatives, nothing a bound cut short.
class PythonLaunchEval
{
public:
    enum class Outcome
    {
        Value,   ///< the value is known
        Unknown, ///< not a Python expression, or its value is unknown, guessed or cut short
        TooDeep, ///< nested past the evaluator's depth bound
    };

    /// The expression's value as Python's str() prints it, but for booleans, which are "true"
    /// and "false" as launch conditions read them; `value` is set with Outcome::Value only.
    static Outcome evaluate(const QString &expression, QString *value);
};

} // namespace rosarch
