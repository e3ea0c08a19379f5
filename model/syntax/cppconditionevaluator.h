#pragma once

#include "syntax/cppmacro.h"

#include <QByteArray>

namespace rosarch {

/// Evaluates the condition of an `#if` / `#elif` the way a compiler does, with the macros
/// known: `defined X`, `defined(X)`, integer literals, the C operators (logical, comparison,
/// arithmetic, bitwise, `?:`), parentheses. A known object-like macro stands for its value; an
/// unknown identifier is 0. A function-like macro (known or not, e.g. `RCLCPP_VERSION_GTE(...)`,
/// `__has_include(...)`) cannot be evaluated without its definition and the headers, so it makes
/// the result undecidable, unless the rest of the expression decides it (`0 && F(x)`).
class CppConditionEvaluator
{
public:
    struct Result
    {
        bool decided = false;
        long long value = 0;
    };

    explicit CppConditionEvaluator(const CppMacros &macros);

    /// Evaluates `condition` (the text after `#if`, comments already removed).
    Result evaluate(const QByteArray &condition) const;

private:
    const CppMacros &m_macros;
};

} // namespace rosarch
