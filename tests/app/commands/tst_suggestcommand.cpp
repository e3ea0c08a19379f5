// End-to-end: the real `rosarch suggest` executable, deterministic only, against a fake
// OpenAI-compatible server, and against an endpoint that refuses connections.
#include "support/fakellmserver.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using rosarch::test::FakeLlmServer;
using rosarch::test::FakeRequest;

namespace {

const QByteArray kKey = "sk-e2e-7d1c0b99";

using rosarch::test::Run;
using rosarch::test::runRosarch;

QString exampleWorkspace()
{
    return QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
        .filePath(QStringLiteral("resources/example_ws"));
}

QJsonObject readJson(const QString &path)
{
    return QJsonDocument::fromJson(rosarch::test::readFile(path)).object();
}

QJsonArray dataBlock(const FakeRequest &r, const QString &name)
{
    const QString user = r.lastMessage();
    const QString open = QStringLiteral("<<<DATA %1\n").arg(name);
    const qsizetype from = user.indexOf(open) + open.size();
    const qsizetype to = user.indexOf(QStringLiteral("\nDATA>>>"), from);
    return QJsonDocument::fromJson(user.mid(from, to - from).toUtf8()).array();
}

/// Cites the numbered excerpt line that contains `quote` ({} when none does).
QJsonObject cite(const QJsonObject &excerpt, const QString &quote)
{
    for (const QJsonValue &v : excerpt.value(QLatin1String("lines")).toArray()) {
        const QString line = v.toString();
        if (line.contains(quote)) {
            const int n = line.section(QLatin1Char('|'), 0, 0).toInt();
            return {{"file", excerpt.value(QLatin1String("file"))},
                    {"line", n},
                    {"end_line", n},
                    {"quote", quote}};
        }
    }
    return {};
}

/// A well-behaved model: describes each node citing its class line, groups the first three
/// instances.
rosarch::test::FakeResponse goodModel(const FakeRequest &r)
{
    QJsonObject reply;
    if (r.schemaName() == QLatin1String("describe_nodes")) {
        QJsonArray list;
        for (const QJsonValue &v : dataBlock(r, QStringLiteral("nodes"))) {
            const QJsonObject n = v.toObject();
            const QJsonObject c =
                cite(n.value("excerpt").toObject(), n.value("class_name").toString());
            if (!c.isEmpty())
                list.append(QJsonObject{{"node_id", n.value("id")},
                                        {"description", QStringLiteral("Fake description of %1.")
                                                            .arg(n.value("class_name").toString())},
                                        {"rationale", "the class"},
                                        {"evidence", QJsonArray{c}}});
        }
        reply.insert("descriptions", list);
    } else if (r.schemaName() == QLatin1String("group_subsystems")) {
        const QJsonArray instances = dataBlock(r, QStringLiteral("instances"));
        QJsonArray members;
        QJsonArray evidence;
        for (int i = 1; i < 4; ++i) { // n2..n4: skip the component container
            const QJsonObject n = instances.at(i).toObject();
            members.append(n.value("id"));
            const QJsonObject c =
                cite(n.value("launch").toObject(), n.value("executable").toString());
            if (!c.isEmpty())
                evidence.append(c);
        }
        reply.insert("groups", QJsonArray{QJsonObject{{"name", "fake_group"},
                                                      {"member_ids", members},
                                                      {"rationale", "shared topics"},
                                                      {"evidence", evidence}}});
    } else {
        reply.insert("candidates", QJsonArray{});
    }
    return FakeLlmServer::stream(QJsonDocument(reply).toJson(QJsonDocument::Compact), 40);
}

QStringList kinds(const QJsonObject &root, const QString &provider)
{
    QStringList out;
    for (const QJsonValue &v : root.value("suggestions").toArray()) {
        const QJsonObject s = v.toObject();
        if (s.value("origin").toObject().value("provider").toString() == provider)
            out << s.value("kind").toString();
    }
    return out;
}

} // namespace

class TestSuggestCommand : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void deterministicWithoutEndpoint()
    {
        QTemporaryDir out;
        const Run r = runRosarch(
            {QStringLiteral("suggest"), exampleWorkspace(), QStringLiteral("--out"), out.path()});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(
                     QStringLiteral("9 suggestions (8 node-description, 1 subsystem-grouping)")),
                 qPrintable(r.out));
        const QJsonObject root = readJson(out.filePath(QStringLiteral("suggestions.json")));
        QCOMPARE(
            kinds(root, QStringLiteral("deterministic")).count(QStringLiteral("node-description")),
            8);
        const QJsonObject group = root.value("suggestions").toArray().at(8).toObject();
        QCOMPARE(group.value("kind").toString(), QStringLiteral("subsystem-grouping"));
        QCOMPARE(group.value("target").toObject().value("id").toString(), QStringLiteral("lf1"));
        QCOMPARE(group.value("proposal").toObject().value("member_ids").toArray(),
                 (QJsonArray{"n2", "n4", "n6", "n7"}));
        QCOMPARE(group.value("status").toString(), QStringLiteral("pending"));
        QCOMPARE(root.value("llm").toObject().value("used").toBool(), false);
        QCOMPARE(root.value("errors").toArray().size(), 0);
        // The prompts are still built and measured, but not sent.
        const QJsonArray prompts = root.value("prompts").toObject().value("list").toArray();
        QCOMPARE(prompts.size(), 3); // two describe_nodes batches and one group_subsystems
        for (const QJsonValue &p : prompts)
            QCOMPARE(p.toObject().value("sent").toBool(), false);
    }

    void fakeServerEndToEnd()
    {
        FakeLlmServer server;
        server.setHandler(goodModel);
        QTemporaryDir out;
        const Run r = runRosarch(
            {QStringLiteral("suggest"), exampleWorkspace(), QStringLiteral("--out"), out.path(),
             QStringLiteral("--llm-endpoint"), server.endpoint() + QStringLiteral("/v1"),
             QStringLiteral("--llm-model"), QStringLiteral("fake-7b"),
             QStringLiteral("--llm-timeout"), QStringLiteral("20")},
            {{QStringLiteral("ROSARCH_LLM_API_KEY"), QString::fromLatin1(kKey)}});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err + r.out));
        QCOMPARE(server.requests().size(), 3);
        for (const FakeRequest &req : server.requests()) {
            QCOMPARE(req.headers.value("authorization"), "Bearer " + kKey);
            QCOMPARE(req.json().value("model").toString(), QStringLiteral("fake-7b"));
            QCOMPARE(req.json().value("stream").toBool(), true);
        }
        const QJsonObject root = readJson(out.filePath(QStringLiteral("suggestions.json")));
        const QStringList llm = kinds(root, QStringLiteral("llm:fake-7b"));
        QCOMPARE(llm.count(QStringLiteral("node-description")), 8);
        QCOMPARE(llm.count(QStringLiteral("subsystem-grouping")), 1);
        QCOMPARE(kinds(root, QStringLiteral("deterministic")).size(), 9);
        QCOMPARE(root.value("discarded").toObject().value("total").toInt(), 0);
        const QJsonArray prompts = root.value("prompts").toObject().value("list").toArray();
        QCOMPARE(prompts.size(), 3);
        for (const QJsonValue &p : prompts) {
            QCOMPARE(p.toObject().value("outcome").toString(), QStringLiteral("ok"));
            QVERIFY(p.toObject().value("estimated_tokens").toInt() > 300);
        }
        // The key goes in the Authorization header and nowhere else.
        QVERIFY(!r.out.contains(QString::fromLatin1(kKey)) &&
                !r.err.contains(QString::fromLatin1(kKey)));
        QVERIFY(r.out.contains(QStringLiteral("key=set (hidden)")));
        QDirIterator files(out.path(), QDir::Files, QDirIterator::Subdirectories);
        int checked = 0;
        while (files.hasNext()) {
            QVERIFY(!rosarch::test::readFile(files.next()).contains(kKey));
            ++checked;
        }
        QCOMPARE(checked, 1);
    }

    void failingEndpointStillWritesDeterministicSuggestions()
    {
        QTcpServer probe;
        probe.listen(QHostAddress::LocalHost, 0);
        const quint16 port = probe.serverPort();
        probe.close();
        QTemporaryDir out;
        const Run r = runRosarch(
            {QStringLiteral("suggest"), exampleWorkspace(), QStringLiteral("--out"), out.path()},
            {{QStringLiteral("ROSARCH_LLM_ENDPOINT"),
              QStringLiteral("http://127.0.0.1:%1").arg(port)}});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QStringLiteral("LLM error: Cannot connect to the LLM endpoint "
                                               "http://127.0.0.1:%1/v1/chat/completions")
                                    .arg(port)),
                 qPrintable(r.err));
        const QJsonObject root = readJson(out.filePath(QStringLiteral("suggestions.json")));
        QCOMPARE(kinds(root, QStringLiteral("deterministic")).size(), 9);
        QCOMPARE(root.value("errors").toArray().size(), 1);
        QCOMPARE(root.value("llm").toObject().value("used").toBool(), true);
    }

    void usageErrors()
    {
        QCOMPARE(runRosarch({QStringLiteral("suggest")}).exitCode, 2);
        QCOMPARE(runRosarch({QStringLiteral("suggest"), exampleWorkspace()}).exitCode, 2);
        const Run timeout = runRosarch({QStringLiteral("suggest"), exampleWorkspace(),
                                        QStringLiteral("--out"), QStringLiteral("/tmp/x"),
                                        QStringLiteral("--llm-timeout"), QStringLiteral("soon")});
        QCOMPARE(timeout.exitCode, 2);
        QVERIFY(timeout.err.contains(QStringLiteral("--llm-timeout")));
        QVERIFY(runRosarch({QStringLiteral("--help")})
                    .out.contains(QStringLiteral("rosarch suggest <workspace> --out <dir>")));
    }
};

QTEST_GUILESS_MAIN(TestSuggestCommand)
#include "tst_suggestcommand.moc"
