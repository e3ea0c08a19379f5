#include "core/diagnostic.h"

#include <QCryptographicHash>
#include <QHash>

#include <algorithm>

namespace rosarch {

QString Diagnostic::severityName(Severity s)
{
    switch (s) {
    case Severity::Info:
        return QStringLiteral("info");
    case Severity::Warning:
        return QStringLiteral("warning");
    case Severity::Error:
        return QStringLiteral("error");
    }
    return {};
}

QString Diagnostic::key() const
{
    const QByteArray text =
        (code + QLatin1Char('\n') + evidence.file + QLatin1Char('\n') + message).toUtf8();
    return code + QLatin1Char(':') +
           QString::fromLatin1(
               QCryptographicHash::hash(text, QCryptographicHash::Sha1).toHex().left(16));
}

void Diagnostic::removeDuplicates(QList<Diagnostic> *list)
{
    QHash<QString, QList<qsizetype>> kept; // code, place and message -> indices in `unique`
    QList<Diagnostic> unique;
    unique.reserve(list->size());
    for (Diagnostic &d : *list) {
        const QString bucket = d.code + QLatin1Char('\n') + d.evidence.file + QLatin1Char(':') +
                               QString::number(d.evidence.line) + QLatin1Char('\n') + d.message;
        QList<qsizetype> &same = kept[bucket];
        if (std::any_of(same.cbegin(), same.cend(), [&](qsizetype i) { return unique.at(i) == d; }))
            continue;
        same.append(unique.size());
        unique.append(std::move(d));
    }
    *list = std::move(unique);
}

} // namespace rosarch
