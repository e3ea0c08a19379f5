#include "suggestions/llm/llmclient.h"
#include "suggestions/llm/llmschemavalidator.h"

#include <QDateTime>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QThread>

#include <curl/curl.h>

#include <mutex>

namespace rosarch {

namespace {

const char *const kFormatNames[] = {"json_schema", "json_object", "none"};

void initCurlOnce()
{
    static std::once_flag once;
    std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

/// What one HTTP exchange produced.
struct Exchange
{
    CURLcode code = CURLE_OK;
    QString curlError;
    long status = 0;
    QByteArray body;
    QByteArray retryAfter;
    // Streaming: content accumulated from SSE `data:` chunks.
    bool streamed = false;
    QByteArray pending; // an incomplete SSE line
    QString content;
    int chunks = 0;
    bool tooLarge = false; ///< the reply passed kMaxReplyBytes; the transfer was stopped
    const LlmRequest *request = nullptr;
};

void consumeSseLine(Exchange *x, const QByteArray &rawLine)
{
    const QByteArray line = rawLine.trimmed();
    if (!line.startsWith("data:"))
        return;
    x->streamed = true;
    const QByteArray payload = line.mid(5).trimmed();
    if (payload == "[DONE]")
        return;
    const QJsonObject chunk = QJsonDocument::fromJson(payload).object();
    const QJsonObject choice = chunk.value(QLatin1String("choices")).toArray().at(0).toObject();
    const QJsonValue delta =
        choice.value(QLatin1String("delta")).toObject().value(QLatin1String("content"));
    if (delta.isString())
        x->content += delta.toString();
    ++x->chunks;
    if (x->request->progressed)
        x->request->progressed(x->content.size(), x->chunks);
}

size_t onWrite(char *data, size_t size, size_t count, void *user)
{
    auto *x = static_cast<Exchange *>(user);
    const size_t n = size * count;
    if (x->body.size() + qsizetype(n) > LlmClient::kMaxReplyBytes) {
        x->tooLarge = true;
        return 0; // libcurl stops the transfer (CURLE_WRITE_ERROR)
    }
    x->body.append(data, qsizetype(n));
    x->pending.append(data, qsizetype(n));
    qsizetype nl;
    while ((nl = x->pending.indexOf('\n')) >= 0) {
        consumeSseLine(x, x->pending.left(nl));
        x->pending.remove(0, nl + 1);
    }
    return n;
}

size_t onHeader(char *data, size_t size, size_t count, void *user)
{
    auto *x = static_cast<Exchange *>(user);
    const QByteArray line(data, qsizetype(size * count));
    if (line.toLower().startsWith("retry-after:"))
        x->retryAfter = line.mid(12).trimmed();
    return size * count;
}

int onProgress(void *user, curl_off_t, curl_off_t, curl_off_t, curl_off_t)
{
    const auto *x = static_cast<Exchange *>(user);
    return x->request->cancel && x->request->cancel->load() ? 1 : 0;
}

Exchange post(const LlmSettings &settings, const LlmRequest &request, const QByteArray &body)
{
    initCurlOnce();
    Exchange x;
    x.request = &request;
    CURL *curl = curl_easy_init();
    if (!curl) {
        x.code = CURLE_FAILED_INIT;
        x.curlError = QStringLiteral("cannot initialise libcurl");
        return x;
    }
    char errorBuffer[CURL_ERROR_SIZE] = {0};
    const QByteArray url = settings.completionsUrl().toUtf8();
    curl_slist *headers = nullptr;
    headers = curl_slist_append(headers, "Content-Type: application/json");
    headers = curl_slist_append(headers, "Expect:"); // no 100-continue round trip
    if (settings.stream)
        headers = curl_slist_append(headers, "Accept: text/event-stream");
    const QString key = LlmSettings::apiKey();
    QByteArray authorization;
    if (!key.isEmpty()) {
        authorization = "Authorization: Bearer " + key.toUtf8();
        headers = curl_slist_append(headers, authorization.constData());
    }
    curl_easy_setopt(curl, CURLOPT_URL, url.constData());
    curl_easy_setopt(curl, CURLOPT_HTTPHEADER, headers);
    curl_easy_setopt(curl, CURLOPT_POST, 1L);
    curl_easy_setopt(curl, CURLOPT_POSTFIELDS, body.constData());
    curl_easy_setopt(curl, CURLOPT_POSTFIELDSIZE_LARGE, curl_off_t(body.size()));
    curl_easy_setopt(curl, CURLOPT_NOSIGNAL, 1L); // worker threads: no SIGALRM for timeouts
    curl_easy_setopt(curl, CURLOPT_CONNECTTIMEOUT_MS, long(settings.connectTimeoutMs));
    curl_easy_setopt(curl, CURLOPT_TIMEOUT_MS, long(settings.requestTimeoutMs));
    curl_easy_setopt(curl, CURLOPT_WRITEFUNCTION, onWrite);
    curl_easy_setopt(curl, CURLOPT_WRITEDATA, &x);
    curl_easy_setopt(curl, CURLOPT_HEADERFUNCTION, onHeader);
    curl_easy_setopt(curl, CURLOPT_HEADERDATA, &x);
    curl_easy_setopt(curl, CURLOPT_NOPROGRESS, 0L);
    curl_easy_setopt(curl, CURLOPT_XFERINFOFUNCTION, onProgress);
    curl_easy_setopt(curl, CURLOPT_XFERINFODATA, &x);
    curl_easy_setopt(curl, CURLOPT_ERRORBUFFER, errorBuffer);
    curl_easy_setopt(curl, CURLOPT_USERAGENT, "rosarch/" ROSARCH_VERSION);
    x.code = curl_easy_perform(curl);
    if (!x.pending.isEmpty())
        consumeSseLine(&x, x.pending);
    curl_easy_getinfo(curl, CURLINFO_RESPONSE_CODE, &x.status);
    x.curlError = QString::fromUtf8(errorBuffer[0] ? errorBuffer : curl_easy_strerror(x.code));
    curl_slist_free_all(headers);
    curl_easy_cleanup(curl);
    return x;
}

QByteArray requestBody(const LlmSettings &settings, const LlmRequest &request,
                       const QList<LlmRequest::Message> &messages, int formatLevel)
{
    QJsonObject body;
    body.insert(QLatin1String("model"), settings.model);
    QJsonArray list;
    for (const LlmRequest::Message &m : messages)
        list.append(
            QJsonObject{{QLatin1String("role"), m.role}, {QLatin1String("content"), m.content}});
    body.insert(QLatin1String("messages"), list);
    body.insert(QLatin1String("temperature"), settings.temperature);
    body.insert(QLatin1String("stream"), settings.stream);
    if (formatLevel == 0) {
        QString name = request.name;
        name.replace(QRegularExpression(QStringLiteral("[^A-Za-z0-9_-]")), QStringLiteral("_"));
        QJsonObject schema{{QLatin1String("name"), name.isEmpty() ? QStringLiteral("reply") : name},
                           {QLatin1String("schema"), request.schema},
                           {QLatin1String("strict"), false}};
        body.insert(QLatin1String("response_format"),
                    QJsonObject{{QLatin1String("type"), QStringLiteral("json_schema")},
                                {QLatin1String("json_schema"), schema}});
    } else if (formatLevel == 1) {
        body.insert(QLatin1String("response_format"),
                    QJsonObject{{QLatin1String("type"), QStringLiteral("json_object")}});
    }
    return QJsonDocument(body).toJson(QJsonDocument::Compact);
}

/// The start of a reply for a message: never raw bytes on a terminal or in the log. Control
/// characters and bytes that are not UTF-8 are shown as escapes (\x00, \xff).
QString excerpt(const QByteArray &data, int max = 200)
{
    QString s;
    const QByteArray head = data.left(max * 4);
    for (qsizetype i = 0; i < head.size() && s.size() < max;) {
        const uchar c = uchar(head.at(i));
        if (c == '\n' || c == '\r' || c == '\t') {
            s += QLatin1Char(' ');
            ++i;
            continue;
        }
        if (c < 0x20 || c == 0x7f) {
            s += QStringLiteral("\\x%1").arg(c, 2, 16, QLatin1Char('0'));
            ++i;
            continue;
        }
        const int length = c < 0x80           ? 1
                           : (c >> 5) == 0x6  ? 2
                           : (c >> 4) == 0xe  ? 3
                           : (c >> 3) == 0x1e ? 4
                                              : 0;
        const QByteArray sequence = length > 0 ? head.mid(i, length) : QByteArray();
        if (length == 0 || sequence.size() < length || !sequence.isValidUtf8()) {
            s += QStringLiteral("\\x%1").arg(c, 2, 16, QLatin1Char('0'));
            ++i;
            continue;
        }
        s += QString::fromUtf8(sequence);
        i += length;
    }
    s = s.simplified();
    if (s.size() >= max || data.size() > head.size())
        s += QStringLiteral("...");
    return s;
}

/// Milliseconds to wait before the next attempt: Retry-After when given, else exponential.
int backoffMs(const LlmSettings &settings, const QByteArray &retryAfter, int attempt)
{
    qint64 ms = -1;
    bool isNumber = false;
    const double seconds = retryAfter.toDouble(&isNumber);
    if (isNumber && seconds >= 0) {
        ms = qint64(seconds * 1000);
    } else if (!retryAfter.isEmpty()) {
        const QDateTime when =
            QDateTime::fromString(QString::fromLatin1(retryAfter), Qt::RFC2822Date);
        if (when.isValid())
            ms = qMax<qint64>(0, QDateTime::currentDateTimeUtc().msecsTo(when));
    }
    if (ms < 0)
        ms = qint64(settings.backoffBaseMs) << qMin(attempt, 16);
    return int(qMin<qint64>(ms, settings.maxBackoffMs));
}

/// Sleeps in short slices so cancellation stays responsive; false when canceled.
bool waitCancelable(int ms, const std::atomic_bool *cancel)
{
    for (int waited = 0; waited < ms; waited += 50) {
        if (cancel && cancel->load())
            return false;
        QThread::msleep(ulong(qMin(50, ms - waited)));
    }
    return !(cancel && cancel->load());
}

/// The JSON inside a reply's content; tolerates a Markdown code fence around it.
QJsonDocument parseContent(const QString &content, QString *error)
{
    QString text = content.trimmed();
    static const QRegularExpression fence(
        QStringLiteral("^```[A-Za-z]*\\s*\\n([\\s\\S]*?)\\n?```$"));
    const QRegularExpressionMatch m = fence.match(text);
    if (m.hasMatch())
        text = m.captured(1);
    QJsonParseError parseError;
    const QJsonDocument doc = QJsonDocument::fromJson(text.toUtf8(), &parseError);
    if (doc.isNull())
        *error = parseError.errorString();
    return doc;
}

} // namespace

qint64 LlmRequest::chars() const
{
    qint64 n = 0;
    for (const Message &m : messages)
        n += m.content.size();
    return n;
}

QString LlmResult::errorName(Error error)
{
    switch (error) {
    case Error::None:
        return QStringLiteral("none");
    case Error::NoEndpoint:
        return QStringLiteral("no-endpoint");
    case Error::ConnectionRefused:
        return QStringLiteral("connection-refused");
    case Error::Timeout:
        return QStringLiteral("timeout");
    case Error::Http:
        return QStringLiteral("http-error");
    case Error::RateLimited:
        return QStringLiteral("rate-limited");
    case Error::NotJson:
        return QStringLiteral("not-json");
    case Error::SchemaMismatch:
        return QStringLiteral("schema-mismatch");
    case Error::Canceled:
        return QStringLiteral("canceled");
    case Error::Network:
        return QStringLiteral("network-error");
    case Error::ReplyTooLarge:
        return QStringLiteral("reply-too-large");
    }
    return QStringLiteral("unknown");
}

LlmClient::LlmClient(const LlmSettings &settings) : m_settings(settings) {}

QJsonDocument LlmClient::parseReply(const QString &content, QString *error)
{
    return parseContent(content, error);
}

LlmResult LlmClient::complete(const LlmRequest &request) const
{
    LlmResult result;
    auto finish = [&](LlmResult::Error error, const QString &message) {
        result.error = error;
        result.message = LlmSettings::masked(message);
        return result;
    };
    if (!m_settings.isConfigured())
        return finish(LlmResult::Error::NoEndpoint,
                      QStringLiteral("No LLM endpoint is configured."));
    const QString url = m_settings.completionsUrl();
    QList<LlmRequest::Message> conversation = request.messages;

    for (int round = 0; round < 2; ++round) {
        Exchange x;
        int retries = 0;
        for (;;) {
            const int level = m_formatLevel.load();
            x = post(m_settings, request, requestBody(m_settings, request, conversation, level));
            ++result.requests;
            result.httpStatus = int(x.status);
            result.responseFormat = QString::fromLatin1(kFormatNames[level]);
            if (x.tooLarge)
                return finish(LlmResult::Error::ReplyTooLarge,
                              QStringLiteral("The reply of the LLM endpoint %1 exceeded %2 MB and "
                                             "was cut off; no suggestion was taken from it. It "
                                             "began: %3")
                                  .arg(url)
                                  .arg(kMaxReplyBytes / (1024 * 1024))
                                  .arg(excerpt(x.body)));
            if (x.code == CURLE_ABORTED_BY_CALLBACK)
                return finish(LlmResult::Error::Canceled,
                              QStringLiteral("The LLM request was canceled."));
            if (x.code == CURLE_COULDNT_CONNECT || x.code == CURLE_COULDNT_RESOLVE_HOST)
                return finish(LlmResult::Error::ConnectionRefused,
                              QStringLiteral("Cannot connect to the LLM endpoint %1: %2")
                                  .arg(url, x.curlError));
            if (x.code == CURLE_OPERATION_TIMEDOUT)
                return finish(
                    LlmResult::Error::Timeout,
                    QStringLiteral("The LLM endpoint %1 did not answer in time (%2): %3")
                        .arg(url)
                        .arg(x.status == 0
                                 ? QStringLiteral("connect timeout %1 s, request timeout %2 s")
                                       .arg(m_settings.connectTimeoutMs / 1000.0)
                                       .arg(m_settings.requestTimeoutMs / 1000.0)
                                 : QStringLiteral("request timeout %1 s")
                                       .arg(m_settings.requestTimeoutMs / 1000.0))
                        .arg(x.curlError));
            if (x.code != CURLE_OK)
                return finish(LlmResult::Error::Network,
                              QStringLiteral("The request to the LLM endpoint %1 failed: %2")
                                  .arg(url, x.curlError));
            const bool formatRejected =
                x.status == 400 && level < 2 &&
                (x.body.contains("response_format") || x.body.contains("json_schema"));
            if (formatRejected) {
                // Older servers (and some Ollama/llama.cpp builds) know only json_object, or
                // nothing.
                int expected = level;
                m_formatLevel.compare_exchange_strong(expected, level + 1);
                continue;
            }
            if ((x.status == 429 || x.status >= 500) && retries < m_settings.maxRetries) {
                if (!waitCancelable(backoffMs(m_settings, x.retryAfter, retries), request.cancel))
                    return finish(LlmResult::Error::Canceled,
                                  QStringLiteral("The LLM request was canceled."));
                ++retries;
                continue;
            }
            break;
        }
        if (x.status == 429)
            return finish(LlmResult::Error::RateLimited,
                          QStringLiteral("The LLM endpoint %1 is rate limiting (HTTP 429) and "
                                         "still was after %2 retries: %3")
                              .arg(url)
                              .arg(retries)
                              .arg(excerpt(x.body)));
        if (x.status >= 400 || x.status < 200)
            return finish(LlmResult::Error::Http,
                          QStringLiteral("The LLM endpoint %1 answered HTTP %2: %3")
                              .arg(url)
                              .arg(x.status)
                              .arg(excerpt(x.body)));

        QString content;
        if (x.streamed) {
            content = x.content;
        } else {
            const QJsonDocument doc = QJsonDocument::fromJson(x.body);
            const QJsonValue message = doc.object()
                                           .value(QLatin1String("choices"))
                                           .toArray()
                                           .at(0)
                                           .toObject()
                                           .value(QLatin1String("message"));
            if (!doc.isObject() || !message.isObject())
                return finish(LlmResult::Error::NotJson,
                              QStringLiteral("The reply of the LLM endpoint %1 is not a "
                                             "chat-completions JSON object: %2")
                                  .arg(url, excerpt(x.body)));
            content = message.toObject().value(QLatin1String("content")).toString();
        }
        result.content = content;

        QString error;
        LlmResult::Error kind = LlmResult::Error::None;
        const QJsonDocument reply = parseContent(content, &error);
        if (reply.isNull()) {
            kind = LlmResult::Error::NotJson;
            error = QStringLiteral("the reply is not JSON (%1): %2")
                        .arg(error, excerpt(content.toUtf8()));
        } else {
            const QJsonValue value =
                reply.isObject() ? QJsonValue(reply.object()) : QJsonValue(reply.array());
            if (LlmSchemaValidator(request.schema).validate(value, &error)) {
                result.json = value;
                return result;
            }
            kind = LlmResult::Error::SchemaMismatch;
            error = QStringLiteral("the reply does not fit the schema: %1").arg(error);
        }
        if (round == 1)
            return finish(kind,
                          QStringLiteral("%1: %2 (also after one retry)").arg(request.name, error));
        // One repair round: show the model its reply and what was wrong with it.
        ++result.repairs;
        conversation.append({QStringLiteral("assistant"), content});
        QString repair = request.repairInstruction.isEmpty() ? QStringLiteral("{{error}}")
                                                             : request.repairInstruction;
        repair.replace(QLatin1String("{{error}}"), error);
        conversation.append({QStringLiteral("user"), repair});
    }
    return result;
}

} // namespace rosarch
