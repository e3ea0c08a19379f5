#include "core/suggestion.h"

namespace rosarch {

QString Suggestion::kindName(Kind kind)
{
    switch (kind) {
    case Kind::NodeDescription:
        return QStringLiteral("node-description");
    case Kind::SubsystemGrouping:
        return QStringLiteral("subsystem-grouping");
    case Kind::NameResolution:
        return QStringLiteral("name-resolution");
    }
    return {};
}

bool Suggestion::kindFromName(const QString &name, Kind *kind)
{
    for (Kind k : {Kind::NodeDescription, Kind::SubsystemGrouping, Kind::NameResolution})
        if (kindName(k) == name) {
            *kind = k;
            return true;
        }
    return false;
}

QString Suggestion::statusName(Status status)
{
    switch (status) {
    case Status::Pending:
        return QStringLiteral("pending");
    case Status::Accepted:
        return QStringLiteral("accepted");
    case Status::Rejected:
        return QStringLiteral("rejected");
    }
    return {};
}

bool Suggestion::statusFromName(const QString &name, Status *status)
{
    for (Status s : {Status::Pending, Status::Accepted, Status::Rejected})
        if (statusName(s) == name) {
            *status = s;
            return true;
        }
    return false;
}

QString Suggestion::subjectKey() const
{
    return kindName(kind) + QLatin1Char('|') + targetId + QLatin1Char('|') +
           memberIds.join(QLatin1Char(','));
}

} // namespace rosarch
