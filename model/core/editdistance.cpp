#include "core/editdistance.h"

#include <QList>

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace rosarch {

int editDistance(const QString &a, const QString &b, int limit)
{
    const qsizetype n = a.size(), m = b.size();
    if (limit < 0) // unbounded: as long as the longer string, which bounds any distance
        limit = int(std::min<qsizetype>(std::max(n, m) + 1, std::numeric_limits<int>::max()));
    if (std::abs(n - m) >= limit)
        return limit;
    // Ukkonen's band: a cell further than `limit` from the diagonal is at least `limit`, so a
    // row computes only 2 * limit + 1 cells, and the work is linear in the length for a fixed
    // limit. Values are capped at `limit`.
    QList<int> row(m + 1);
    for (qsizetype j = 0; j <= m; ++j)
        row[j] = int(std::min<qsizetype>(j, limit));
    for (qsizetype i = 1; i <= n; ++i) {
        const qsizetype lo = std::max<qsizetype>(1, i - limit);
        const qsizetype hi = std::min<qsizetype>(m, i + limit);
        int diagonal = row[lo - 1];
        row[lo - 1] = lo == 1 ? int(std::min<qsizetype>(i, limit)) : limit;
        int rowMinimum = row[lo - 1];
        for (qsizetype j = lo; j <= hi; ++j) {
            const int up = row[j];
            row[j] = std::min(
                {up + 1, row[j - 1] + 1, diagonal + (a.at(i - 1) == b.at(j - 1) ? 0 : 1), limit});
            diagonal = up;
            rowMinimum = std::min(rowMinimum, row[j]);
        }
        if (rowMinimum >= limit)
            return limit; // a row's minimum never decreases further down
    }
    return std::min(limit, row[m]);
}

} // namespace rosarch
