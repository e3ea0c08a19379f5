#pragma once

#include <QJsonValue>
#include <QString>

namespace rosarch {

/// The outcome of one LlmClient::complete call: the validated JSON, or why there is none.
struct LlmResult
{
    enum class Error
    {
        None,
        NoEndpoint,        ///< nothing configured
        ConnectionRefused, ///< nobody listens there / host not found
        Timeout,           ///< connect or request timeout
        Http,              ///< a 4xx/5xx status (httpStatus, body excerpt in message)
        RateLimited,       ///< 429 after every bounded retry
        NotJson,           ///< the reply (or its content) is not JSON
        SchemaMismatch,    ///< valid JSON that does not fit the schema, also after the repair retry
        Canceled,
        Network,       ///< any other transfer failure
        ReplyTooLarge, ///< the reply exceeded LlmClient::kMaxReplyBytes and was cut off
    };

    Error error = Error::None;
    QString message;        ///< clear, user-facing; never contains the API key
    int httpStatus = 0;     ///< of the last response
    QJsonValue json;        ///< the validated reply
    QString content;        ///< the raw content of the last reply
    int requests = 0;       ///< HTTP requests made (retries and fallbacks included)
    int repairs = 0;        ///< conversations retried with a validation error
    QString responseFormat; ///< "json_schema", "json_object" or "none": what the server accepted

    bool ok() const { return error == Error::None; }
    /// "no-endpoint", "connection-refused", ... for reports and counts.
    static QString errorName(Error error);
};

} // namespace rosarch
