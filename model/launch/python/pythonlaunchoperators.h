#pragma once

#include "launch/python/pythonlaunchvalue.h"

#include <QString>

#include <optional>
#include <string_view>

namespace rosarch::pylaunch {

// What Python's literals and operators mean on symbolic values.

/// The text of a string literal's body with its backslash escapes decoded.
QString decodeEscapes(const QString &s);
/// A value as the text it contributes to a string (f-strings, concatenation).
Substitution asText(const Value &v);
/// `a op b` for a comparison operator, when both sides are known enough to decide it.
std::optional<bool> compare(std::string_view op, const Value &a, const Value &b);

} // namespace rosarch::pylaunch
