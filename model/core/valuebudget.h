#pragma once

#include <QtGlobal>

namespace rosarch {

/// The longest value, in characters, that evaluation builds: a CMake variable, a launch
/// substitution or argument, a name. Names and values of real systems stay far below it; a
/// value doubled in a loop reaches it in a few steps. Past it the value is dropped as
/// unresolved with an `evaluation-limit` diagnostic, so that memory grows with the input, not
/// with what the input computes.
constexpr qsizetype kMaxValueChars = 256 * 1024;

} // namespace rosarch
