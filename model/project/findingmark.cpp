#include "project/findingmark.h"

namespace rosarch {

QString FindingMark::statusName(Status status)
{
    return status == Status::Accepted ? QStringLiteral("accepted") : QStringLiteral("hidden");
}

QJsonObject FindingMark::toJson() const
{
    QJsonObject o{{QLatin1String("key"), key}, {QLatin1String("status"), statusName(status)}};
    if (!reason.isEmpty())
        o.insert(QLatin1String("reason"), reason);
    if (!author.isEmpty())
        o.insert(QLatin1String("author"), author);
    if (time.isValid())
        o.insert(QLatin1String("time"), time.toUTC().toString(Qt::ISODate));
    return o;
}

bool FindingMark::fromJson(const QJsonObject &o, FindingMark *mark, QString *error)
{
    FindingMark m;
    m.key = o.value(QLatin1String("key")).toString();
    const QString status = o.value(QLatin1String("status")).toString();
    if (m.key.isEmpty() ||
        (status != QLatin1String("hidden") && status != QLatin1String("accepted"))) {
        *error = QStringLiteral("a finding needs a key and a status (hidden or accepted)");
        return false;
    }
    m.status = status == QLatin1String("accepted") ? Status::Accepted : Status::Hidden;
    m.reason = o.value(QLatin1String("reason")).toString();
    m.author = o.value(QLatin1String("author")).toString();
    if (o.contains(QLatin1String("time"))) {
        m.time = QDateTime::fromString(o.value(QLatin1String("time")).toString(), Qt::ISODate);
        if (!m.time.isValid()) {
            *error = QStringLiteral("the finding %1 has a time that is not ISO 8601").arg(m.key);
            return false;
        }
        m.time = m.time.toUTC();
    }
    *mark = m;
    return true;
}

} // namespace rosarch
