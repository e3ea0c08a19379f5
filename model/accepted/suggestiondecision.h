#pragma once

#include "core/suggestion.h"

#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace rosarch {

/// What a person decided about one proposal: the suggestion's subject (kind, target, members)
/// and proposed value, accepted or rejected. Kept per workspace so later runs do not ask again.
struct SuggestionDecision
{
    Suggestion::Kind kind = Suggestion::Kind::NodeDescription;
    QString targetId;
    QStringList memberIds;
    QString proposal;
    Suggestion::Status status = Suggestion::Status::Accepted;
    QDateTime decided; ///< UTC

    bool operator==(const SuggestionDecision &) const = default;

    /// The decision `status` on `suggestion`, taken now.
    static SuggestionDecision of(const Suggestion &suggestion, Suggestion::Status status);
    /// Identifies subject and proposal; equal for every suggestion it applies to.
    QString key() const;
    /// The key a decision on `suggestion` has.
    static QString keyOf(const Suggestion &suggestion);

    QJsonObject toJson() const;
    /// False when `o` is not a decision (unknown kind or status, no target).
    static bool fromJson(const QJsonObject &o, SuggestionDecision *decision);
};

} // namespace rosarch
