#include "diagnostic.h"

#include <QCryptographicHash>

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

} // namespace rosarch
