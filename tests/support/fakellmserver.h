#pragma once

// A fake OpenAI-compatible chat-completions server over real HTTP (QTcpServer), header-only
// and without Q_OBJECT so that any test can include it. It serves on the thread that owns it;
// run the client call in a worker thread while the test's event loop spins.
#include <QHostAddress>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QList>
#include <QMap>
#include <QPointer>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

#include <functional>
#include <memory>

namespace rosarch::test {

/// One scripted answer.
struct FakeResponse
{
    int status = 200;
    QByteArray body;
    QList<QByteArray> headers;   ///< extra header lines, e.g. "Retry-After: 1"
    QList<QByteArray> sseChunks; ///< non-empty: answer as text/event-stream, one write each
    bool hang = false;           ///< accept the request and never answer
};

/// One request as received.
struct FakeRequest
{
    QByteArray method;
    QByteArray path;
    QMap<QByteArray, QByteArray> headers; ///< lower-case names
    QByteArray body;

    QJsonObject json() const { return QJsonDocument::fromJson(body).object(); }
    QJsonArray messages() const { return json().value(QLatin1String("messages")).toArray(); }
    /// The last message's content.
    QString lastMessage() const
    {
        return messages().last().toObject().value(QLatin1String("content")).toString();
    }
    /// The prompt name the client put into response_format, else "" (json_object / none).
    QString schemaName() const
    {
        return json()
            .value(QLatin1String("response_format"))
            .toObject()
            .value(QLatin1String("json_schema"))
            .toObject()
            .value(QLatin1String("name"))
            .toString();
    }
    QString responseFormat() const
    {
        return json()
            .value(QLatin1String("response_format"))
            .toObject()
            .value(QLatin1String("type"))
            .toString();
    }
};

class FakeLlmServer
{
public:
    /// A local port nothing listens on (for "connection refused").
    static quint16 closedPort()
    {
        QTcpServer probe;
        probe.listen(QHostAddress::LocalHost, 0);
        const quint16 port = probe.serverPort();
        probe.close();
        return port;
    }

    FakeLlmServer()
    {
        m_server.listen(QHostAddress::LocalHost, 0);
        QObject::connect(&m_server, &QTcpServer::newConnection, &m_server, [this] {
            while (QTcpSocket *socket = m_server.nextPendingConnection()) {
                auto buffer = std::make_shared<QByteArray>();
                QObject::connect(socket, &QTcpSocket::readyRead, socket, [this, socket, buffer] {
                    buffer->append(socket->readAll());
                    serveIfComplete(socket, buffer.get());
                });
            }
        });
    }

    quint16 port() const { return m_server.serverPort(); }
    /// "http://127.0.0.1:<port>" (no /v1: the client adds it).
    QString endpoint() const { return QStringLiteral("http://127.0.0.1:%1").arg(port()); }
    /// Answers in order; when the queue is empty the handler (else the last answer) is used.
    void enqueue(const FakeResponse &r) { m_queue.append(r); }
    void setHandler(std::function<FakeResponse(const FakeRequest &)> handler)
    {
        m_handler = std::move(handler);
    }
    const QList<FakeRequest> &requests() const { return m_requests; }

    /// A non-streamed chat completion whose message content is `content`.
    static FakeResponse chat(const QByteArray &content)
    {
        const QJsonObject message{{QLatin1String("role"), QStringLiteral("assistant")},
                                  {QLatin1String("content"), QString::fromUtf8(content)}};
        const QJsonObject body{
            {QLatin1String("id"), QStringLiteral("chatcmpl-1")},
            {QLatin1String("object"), QStringLiteral("chat.completion")},
            {QLatin1String("choices"),
             QJsonArray{QJsonObject{{QLatin1String("index"), 0},
                                    {QLatin1String("message"), message},
                                    {QLatin1String("finish_reason"), QStringLiteral("stop")}}}}};
        FakeResponse r;
        r.body = QJsonDocument(body).toJson(QJsonDocument::Compact);
        return r;
    }
    /// The same content streamed as SSE chunks of `pieceSize` characters, then [DONE].
    static FakeResponse stream(const QByteArray &content, int pieceSize)
    {
        FakeResponse r;
        const QString text = QString::fromUtf8(content);
        for (qsizetype i = 0; i < text.size(); i += pieceSize) {
            const QJsonObject delta{{QLatin1String("content"), text.mid(i, pieceSize)}};
            const QJsonObject chunk{
                {QLatin1String("object"), QStringLiteral("chat.completion.chunk")},
                {QLatin1String("choices"),
                 QJsonArray{
                     QJsonObject{{QLatin1String("index"), 0}, {QLatin1String("delta"), delta}}}}};
            r.sseChunks << "data: " + QJsonDocument(chunk).toJson(QJsonDocument::Compact) + "\n\n";
        }
        r.sseChunks << QByteArray("data: [DONE]\n\n");
        return r;
    }
    static FakeResponse status(int code, const QByteArray &body,
                               const QList<QByteArray> &headers = {})
    {
        FakeResponse r;
        r.status = code;
        r.body = body;
        r.headers = headers;
        return r;
    }

private:
    void serveIfComplete(QTcpSocket *socket, QByteArray *buffer)
    {
        const qsizetype end = buffer->indexOf("\r\n\r\n");
        if (end < 0)
            return;
        FakeRequest request;
        const QList<QByteArray> lines = buffer->left(end).split('\n');
        const QList<QByteArray> first = lines.value(0).trimmed().split(' ');
        request.method = first.value(0);
        request.path = first.value(1);
        qsizetype length = 0;
        for (qsizetype i = 1; i < lines.size(); ++i) {
            const qsizetype colon = lines[i].indexOf(':');
            if (colon <= 0)
                continue;
            const QByteArray name = lines[i].left(colon).trimmed().toLower();
            request.headers.insert(name, lines[i].mid(colon + 1).trimmed());
            if (name == "content-length")
                length = lines[i].mid(colon + 1).trimmed().toLongLong();
        }
        if (buffer->size() < end + 4 + length)
            return;
        request.body = buffer->mid(end + 4, length);
        buffer->clear();
        m_requests.append(request);
        FakeResponse response;
        if (!m_queue.isEmpty())
            response = m_queue.takeFirst();
        else if (m_handler)
            response = m_handler(request);
        else
            response = m_last;
        m_last = response;
        respond(socket, response);
    }

    void respond(QTcpSocket *socket, const FakeResponse &r)
    {
        if (r.hang)
            return;
        QByteArray head = "HTTP/1.1 " + QByteArray::number(r.status) +
                          (r.status < 400 ? " OK" : " Error") + "\r\n";
        head += r.sseChunks.isEmpty()
                    ? "Content-Type: application/json\r\nContent-Length: " +
                          QByteArray::number(r.body.size()) + "\r\n"
                    : QByteArray("Content-Type: text/event-stream\r\nCache-Control: no-cache\r\n");
        head += "Connection: close\r\n";
        for (const QByteArray &h : r.headers)
            head += h + "\r\n";
        head += "\r\n";
        if (r.sseChunks.isEmpty()) {
            socket->write(head + r.body);
            socket->disconnectFromHost();
            return;
        }
        socket->write(head);
        // One chunk every 20 ms, so the client really sees them arrive separately.
        QPointer<QTcpSocket> guard(socket);
        for (qsizetype i = 0; i <= r.sseChunks.size(); ++i)
            QTimer::singleShot(int(20 * (i + 1)), socket, [guard, r, i] {
                if (!guard)
                    return;
                if (i < r.sseChunks.size()) {
                    guard->write(r.sseChunks[i]);
                    guard->flush();
                } else {
                    guard->disconnectFromHost();
                }
            });
    }

    QTcpServer m_server;
    QList<FakeResponse> m_queue;
    FakeResponse m_last = chat("{}");
    std::function<FakeResponse(const FakeRequest &)> m_handler;
    QList<FakeRequest> m_requests;
};

} // namespace rosarch::test
