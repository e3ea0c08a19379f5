#include "accepted/suggestiondecision.h"

#include <QJsonArray>

namespace rosarch {

SuggestionDecision SuggestionDecision::of(const Suggestion &suggestion, Suggestion::Status status)
{
    SuggestionDecision d;
    d.kind = suggestion.kind;
    d.targetId = suggestion.targetId;
    d.memberIds = suggestion.memberIds;
    d.proposal = suggestion.value;
    d.status = status;
    d.decided = QDateTime::currentDateTimeUtc();
    return d;
}

QString SuggestionDecision::key() const
{
    Suggestion s;
    s.kind = kind;
    s.targetId = targetId;
    s.memberIds = memberIds;
    s.value = proposal;
    return keyOf(s);
}

QString SuggestionDecision::keyOf(const Suggestion &suggestion)
{
    // The unit separator cannot occur in ids or in a one-line proposal.
    return suggestion.subjectKey() + QChar(0x1f) + suggestion.value;
}

QJsonObject SuggestionDecision::toJson() const
{
    return {{QLatin1String("kind"), Suggestion::kindName(kind)},
            {QLatin1String("target"), targetId},
            {QLatin1String("members"), QJsonArray::fromStringList(memberIds)},
            {QLatin1String("proposal"), proposal},
            {QLatin1String("status"), Suggestion::statusName(status)},
            {QLatin1String("decided"), decided.toString(Qt::ISODate)}};
}

bool SuggestionDecision::fromJson(const QJsonObject &o, SuggestionDecision *decision)
{
    SuggestionDecision d;
    if (!Suggestion::kindFromName(o.value(QLatin1String("kind")).toString(), &d.kind) ||
        !Suggestion::statusFromName(o.value(QLatin1String("status")).toString(), &d.status) ||
        d.status == Suggestion::Status::Pending)
        return false;
    d.targetId = o.value(QLatin1String("target")).toString();
    if (d.targetId.isEmpty())
        return false;
    for (const QJsonValue &m : o.value(QLatin1String("members")).toArray())
        d.memberIds << m.toString();
    d.proposal = o.value(QLatin1String("proposal")).toString();
    d.decided = QDateTime::fromString(o.value(QLatin1String("decided")).toString(), Qt::ISODate);
    *decision = d;
    return true;
}

} // namespace rosarch
