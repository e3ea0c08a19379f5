#include "editdistance.h"

#include <QList>

#include <algorithm>
#include <cstdlib>

namespace rosarch {

int editDistance(const QString &a, const QString &b, int limit)
{
    const bool bounded = limit >= 0;
    if (bounded && std::abs(a.size() - b.size()) >= limit)
        return limit;
    QList<int> row(b.size() + 1);
    for (qsizetype j = 0; j <= b.size(); ++j)
        row[j] = int(j);
    for (qsizetype i = 1; i <= a.size(); ++i) {
        int diagonal = row[0];
        row[0] = int(i);
        int rowMinimum = row[0];
        for (qsizetype j = 1; j <= b.size(); ++j) {
            const int up = row[j];
            row[j] = std::min(
                {row[j] + 1, row[j - 1] + 1, diagonal + (a.at(i - 1) == b.at(j - 1) ? 0 : 1)});
            diagonal = up;
            rowMinimum = std::min(rowMinimum, row[j]);
        }
        if (bounded && rowMinimum >= limit)
            return limit; // a row's minimum never decreases further down
    }
    return bounded ? std::min(limit, row[b.size()]) : row[b.size()];
}

} // namespace rosarch
