#include "suggestions/suggestionsource.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>

namespace rosarch {

SuggestionSource::SuggestionSource(const QString &workspaceRoot) : m_root(workspaceRoot) {}

QStringList SuggestionSource::lines(const QString &file) const
{
    if (file.isEmpty())
        return {};
    auto it = m_cache.find(file);
    if (it == m_cache.end()) {
        QFile f(QDir(m_root).filePath(file));
        QStringList split;
        if (f.open(QIODevice::ReadOnly)) {
            QString text = QString::fromUtf8(f.readAll());
            text.replace(QLatin1String("\r\n"), QLatin1String("\n"));
            split = text.split(QLatin1Char('\n'));
            if (text.endsWith(QLatin1Char('\n')))
                split.removeLast();
        }
        it = m_cache.insert(file, split);
    }
    return *it;
}

QJsonObject SuggestionSource::excerpt(const QString &file, int first, int last, int maxLines) const
{
    const QStringList all = lines(file);
    first = qMax(1, first);
    last = qMin(int(all.size()), qMax(first, last));
    last = qMin(last, first + maxLines - 1);
    QJsonArray numbered;
    for (int l = first; l <= last; ++l)
        numbered.append(QStringLiteral("%1| %2").arg(l).arg(all.at(l - 1)));
    return {{QLatin1String("file"), file},
            {QLatin1String("first_line"), first},
            {QLatin1String("lines"), numbered}};
}

} // namespace rosarch
