#pragma once

#include "core/suggestion.h"
#include "pipeline/recovery.h"
#include "suggestions/suggestionsource.h"

#include <QDateTime>
#include <QList>

namespace rosarch {

/// Suggestions without a language model: node descriptions from the docstring or the comment
/// block above the node class, and subsystem groupings from the communication graph of each
/// root launch file (SubsystemGrouper). They go through the same checker and review.
class DeterministicProvider
{
public:
    DeterministicProvider(const QString &workspaceRoot, const Recovery &recovery,
                          const QDateTime &timestamp = QDateTime::currentDateTimeUtc());

    /// One node-description per ARC that has a docstring or a leading comment.
    QList<Suggestion> describeNodes() const;
    /// The groups of every root launch file, evidence = the launch lines of the members.
    QList<Suggestion> groupSubsystems() const;
    /// Both, descriptions first.
    QList<Suggestion> suggest() const;

private:
    Suggestion make(Suggestion::Kind kind) const;

    const Recovery &m_recovery;
    SuggestionSource m_source;
    QDateTime m_timestamp;
};

} // namespace rosarch
