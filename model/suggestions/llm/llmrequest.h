#pragma once

#include <QJsonObject>
#include <QList>
#include <QString>

#include <atomic>
#include <functional>

namespace rosarch {

/// One chat-completions call: the conversation, the schema the reply must fit, and hooks.
struct LlmRequest
{
    struct Message
    {
        QString role; ///< "system", "user" or "assistant"
        QString content;
    };

    QString name; ///< the prompt's name, for messages and reports
    QList<Message> messages;
    QJsonObject schema; ///< JSON Schema of the reply (empty = any JSON value)
    /// Appended as a user message when a reply does not fit; "{{error}}" is replaced by the
    /// validation error. Comes from a prompt file (prompts/repair_reply.md).
    QString repairInstruction;
    /// Called while a streamed reply arrives: characters and stream chunks received so far.
    std::function<void(qint64 chars, int chunks)> progressed;
    /// Polled by the transfer; setting it aborts the call with LlmResult::Canceled.
    const std::atomic_bool *cancel = nullptr;

    /// Characters of all messages: the size of what is sent (tokens are estimated as chars/4).
    qint64 chars() const;
};

} // namespace rosarch
