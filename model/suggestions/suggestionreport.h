#pragma once

#include "core/suggestion.h"

#include <QList>
#include <QMap>
#include <QString>
#include <QStringList>

namespace rosarch {

/// What a suggestion run produced: the checked suggestions, what was discarded and why, the
/// prompts built (with their size) and the failures met on the way.
struct SuggestionReport
{
    /// One prompt built for the LLM; tokens are estimated as characters / 4.
    struct PromptUsage
    {
        QString prompt; ///< template name
        QString scope;  ///< what it covers: node ids of the batch, the root launch id, item ids
        qint64 chars = 0;
        qint64 estimatedTokens = 0;
        bool sent = false; ///< false when not sent (no endpoint, or an earlier failure)
        int requests = 0;  ///< HTTP requests it took (retries included)
        QString outcome;   ///< "ok" or the LlmResult error name
        bool operator==(const PromptUsage &) const = default;
    };

    QList<Suggestion> suggestions;
    QMap<QString, int> discarded; ///< reason -> count
    QStringList discardedDetails; ///< one line per discarded item, for review
    QList<PromptUsage> prompts;
    QStringList errors; ///< LLM failures, user-facing
    bool llmUsed = false;
    QString llmModel;

    int discardedTotal() const;
    /// Counts one discarded item under `reason`, with a detail line.
    void discard(const QString &reason, const QString &detail);
};

} // namespace rosarch
