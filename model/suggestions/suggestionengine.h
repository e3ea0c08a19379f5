#pragma once

#include "pipeline/recovery.h"
#include "suggestions/llm/llmrequest.h"
#include "suggestions/llm/llmsettings.h"
#include "suggestions/suggestionreport.h"

#include <QList>
#include <QString>

#include <atomic>
#include <functional>

namespace rosarch {

/// Runs the suggestion tasks on the artifacts of stages 1 and 2: the deterministic provider,
/// then (with an endpoint) the LLM prompts describe_nodes, group_subsystems and resolve_names.
/// Every suggestion goes through SuggestionChecker; what fails is discarded and counted.
class SuggestionEngine
{
public:
    struct Options
    {
        LlmSettings llm; ///< used when llm.isConfigured()
        bool deterministic = true;
        QString promptDir;         ///< user folder overriding prompts/ ("" = $ROSARCH_PROMPT_DIR)
        int batchSize = 6;         ///< nodes per describe_nodes prompt
        int maxBatchChars = 16000; ///< and at most this much node data per prompt
        /// One line per step ("describe_nodes arc_1..arc_6: 1234 tokens"); may be null.
        std::function<void(const QString &)> logged;
        /// Streaming progress of the current prompt; may be null.
        std::function<void(const QString &prompt, qint64 chars)> progressed;
        const std::atomic_bool *cancel = nullptr;
    };

    /// A prompt ready to send, with what it covers.
    struct PromptJob
    {
        QString scope;    ///< node ids of the batch, the root launch id, or item ids
        QString launchId; ///< group_subsystems: the root it groups
        LlmRequest request;
    };

    SuggestionEngine(const QString &workspaceRoot, const Recovery &recovery,
                     const Options &options);

    /// Everything: checked suggestions, discarded counts, prompt sizes, LLM errors.
    SuggestionReport run() const;

    /// The prompts of each LLM task (also built without an endpoint, to report their size).
    QList<PromptJob> describeJobs() const;
    QList<PromptJob> groupJobs() const;
    QList<PromptJob> resolveJobs() const;
    /// Estimated tokens of a text size: characters / 4, rounded up.
    static qint64 estimateTokens(qint64 chars) { return (chars + 3) / 4; }

private:
    LlmRequest prepare(const QString &prompt, const QMap<QString, QString> &values) const;

    QString m_root;
    const Recovery &m_recovery;
    Options m_options;
};

} // namespace rosarch
