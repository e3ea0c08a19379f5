#pragma once

#include <QString>

namespace rosarch {

/// The small Python expressions launch files put in `$(eval ...)` and `PythonExpression`, once
/// their substitutions are replaced by text: string, number, boolean and list literals; `==`,
/// `!=`, `<`, `<=`, `>`, `>=`, `in`, `not in`; `not`, `and`, `or`; `+` and `-`; `a if c else b`;
/// subscripts (`[1]`, `[-1]`); the string methods split, strip, lower, upper, replace,
/// startswith and endswith; `len`, `str`, `int`, `float` and `bool`. Anything else (a name, an
/// import, an unknown method) is refused, so that the caller keeps the expression unresolved.
class PythonExpression
{
public:
    /// Nesting deeper than this (parentheses, lists, calls, `not`) is refused.
    static constexpr int kMaxDepth = 64;

    /// The value of `expression` as Python's str() would print it, except that booleans are
    /// "true" and "false" as launch conditions read them; false when it is beyond the subset,
    /// with `tooDeep` set when the reason is nesting past kMaxDepth.
    static bool evaluate(const QString &expression, QString *value, bool *tooDeep = nullptr);
};

} // namespace rosarch
