#pragma once

#include <QString>

namespace rosarch {

/// Where and how to ask an OpenAI-compatible chat-completions server. Holds no secret: the API
/// key is read from the environment at request time and is never stored or written.
struct LlmSettings
{
    QString endpoint; ///< e.g. "http://localhost:11434" or ".../v1" ("" = no LLM)
    QString model = QStringLiteral("gpt-4o-mini");
    double temperature = 0.0; ///< 0 keeps replies as repeatable as the server allows
    int connectTimeoutMs = 10000;
    int requestTimeoutMs = 120000;
    int maxRetries = 3;       ///< for 429 and 5xx replies
    int backoffBaseMs = 1000; ///< first back-off; doubles per retry
    int maxBackoffMs = 30000; ///< cap for Retry-After and the exponential back-off
    bool stream = true;       ///< ask for SSE so progress can be shown

    bool isConfigured() const { return !endpoint.trimmed().isEmpty(); }
    /// The full chat-completions URL, accepting an endpoint given with or without "/v1".
    QString completionsUrl() const;
    /// The endpoint from $ROSARCH_LLM_ENDPOINT and the model from $ROSARCH_LLM_MODEL, if set.
    static LlmSettings fromEnvironment();
    /// $ROSARCH_LLM_API_KEY, else $OPENAI_API_KEY ("" when neither is set).
    static QString apiKey();
    /// Replaces every occurrence of the API key in `text` so it can be shown or logged.
    static QString masked(const QString &text);
    /// A one-line description for logs, with the key shown only as set / not set.
    QString describe() const;
};

} // namespace rosarch
