#pragma once

#include <QJsonDocument>

#include "suggestions/llm/llmrequest.h"
#include "suggestions/llm/llmresult.h"
#include "suggestions/llm/llmsettings.h"

#include <atomic>

namespace rosarch {

/// A synchronous client for OpenAI-compatible `POST /v1/chat/completions` over libcurl.
/// Safe to call from worker threads: every call uses its own CURL easy handle.
class LlmClient
{
public:
    /// A reply larger than this is cut off and reported (a chat completion is kilobytes).
    static constexpr qsizetype kMaxReplyBytes = 16 * 1024 * 1024;
    explicit LlmClient(const LlmSettings &settings);

    /// Sends the conversation, asking for JSON that fits `request.schema`; retries 429/5xx with
    /// bounded back-off, falls back from json_schema to json_object to no response_format when
    /// the server rejects it (400), and retries once with the validation error appended.
    LlmResult complete(const LlmRequest &request) const;
    const LlmSettings &settings() const { return m_settings; }
    /// The JSON inside a reply's content (a Markdown code fence around it is tolerated); a
    /// null document, with `error`, when there is none.
    static QJsonDocument parseReply(const QString &content, QString *error);

private:
    LlmSettings m_settings;
    /// 0 json_schema, 1 json_object, 2 none; remembered so later calls skip rejected formats.
    mutable std::atomic_int m_formatLevel{0};
};

} // namespace rosarch
