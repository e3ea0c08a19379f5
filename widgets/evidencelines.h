#pragma once

#include "core/evidence.h"

#include <algorithm>

namespace rosarch {

/// Whether `e` covers line `line` of `file` (a missing end means the start line only); then
/// `span` is how many lines it spans past its first, so that the innermost of several
/// elements on a line can be chosen.
inline bool coversLine(const Evidence &e, const QString &file, int line, int *span)
{
    if (!e.isValid() || e.file != file)
        return false;
    const int end = std::max(e.endLine, e.line);
    if (line < e.line || line > end)
        return false;
    *span = end - e.line;
    return true;
}

} // namespace rosarch
