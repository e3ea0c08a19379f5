#pragma once

#include <QString>

namespace rosarch {

/// Levenshtein distance between two strings: the fewest single-character insertions,
/// deletions and substitutions that turn `a` into `b` (for "did you mean" hints).
/// With `limit`, any distance of `limit` or more is returned as `limit`, and the work stops as
/// soon as that is certain (for finding near names among many): the work is then about
/// `limit` times the length, not the product of the lengths.
int editDistance(const QString &a, const QString &b, int limit = -1);

} // namespace rosarch
