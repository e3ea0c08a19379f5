#pragma once

#include <QString>

namespace rosarch {

/// Levenshtein distance between two strings: the fewest single-character insertions,
/// deletions and substitutions that turn `a` into `b` (for "did you mean" hints).
int editDistance(const QString &a, const QString &b);

} // namespace rosarch
