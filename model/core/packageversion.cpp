#include "core/packageversion.h"

#include <QStringList>

#include <algorithm>

namespace rosarch {

int compareVersions(const QString &a, const QString &b)
{
    const QStringList x = a.split(QLatin1Char('.')), y = b.split(QLatin1Char('.'));
    for (qsizetype i = 0; i < std::max(x.size(), y.size()); ++i) {
        const qlonglong u = i < x.size() ? x.at(i).toLongLong() : 0;
        const qlonglong v = i < y.size() ? y.at(i).toLongLong() : 0;
        if (u != v)
            return u < v ? -1 : 1;
    }
    return 0;
}

} // namespace rosarch
