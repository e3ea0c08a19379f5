// The suggestion flow behind the panel: the Document's accept / reject / accept-all commands
// (undo round trips), decisions kept per workspace, the runner off the UI thread (stale
// results, cancel) and the controller against a fake OpenAI-compatible server over real HTTP.
#include "app/appsettings.h"
#include "app/suggestioncontroller.h"
#include "app/suggestionrunner.h"
#include "document/document.h"
#include "project/project.h"
#include "suggestions/suggestionengine.h"
#include "support/documentchanges.h"
#include "support/fakellmserver.h"
#include "support/screenshot.h"
#include "support/suggestionfixture.h"
#include "support/testsupport.h"
#include "widgets/suggestionmodel.h"
#include "widgets/suggestionpanel.h"

#include <QLabel>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;
using rosarch::test::exampleWorkspace;
using rosarch::test::FakeLlmServer;
using rosarch::test::FakeRequest;
using rosarch::test::FakeResponse;
using rosarch::test::kSecret;

namespace {

const QString kBattery = QStringLiteral("src/robot_mission/robot_mission/battery_monitor.py");

/// Everything a decision can touch, to compare before / after / undo / redo.
struct Snapshot
{
    QStringList descriptions;
    QStringList statuses;
    QStringList decisions;
    QList<SubsystemGroup> groupings;
    QMap<QString, QString> names;
    bool operator==(const Snapshot &) const = default;
};

Snapshot snapshot(const Document &doc)
{
    Snapshot s;
    for (const AtomicNode &n : doc.atomicNodes().nodes)
        s.descriptions << n.id + QLatin1Char('=') + n.description;
    for (const Suggestion &x : doc.session()->suggestions())
        s.statuses << x.id + QLatin1Char('=') + Suggestion::statusName(x.status);
    for (const SuggestionDecision &d : doc.session()->decisions())
        s.decisions << Suggestion::kindName(d.kind) + QLatin1Char(' ') + d.targetId +
                           QLatin1Char(' ') + d.proposal + QLatin1Char(' ') +
                           Suggestion::statusName(d.status);
    s.groupings = doc.session()->acceptedGroupings();
    s.names = doc.session()->acceptedNames();
    return s;
}

QString describe(const Snapshot &s)
{
    return (s.descriptions + s.statuses + s.decisions).join(QLatin1Char('\n'));
}

QByteArray json(const QJsonObject &o)
{
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

/// A describe_nodes reply for arc_1 citing the docstring of battery_monitor.py (when the
/// prompt is about arc_1); empty lists for everything else.
FakeResponse reply(const FakeRequest &r, bool stream)
{
    QByteArray content = r.schemaName() == QLatin1String("group_subsystems") ? "{\"groups\":[]}"
                         : r.schemaName() == QLatin1String("resolve_names")
                             ? "{\"candidates\":[]}"
                             : "{\"descriptions\":[]}";
    if (r.schemaName() == QLatin1String("describe_nodes") &&
        r.lastMessage().contains(QLatin1String("\"id\":\"arc_1\""))) {
        const QJsonObject item{
            {"node_id", "arc_1"},
            {"description", "Watches the battery charge and warns when it runs low."},
            {"rationale", "The class docstring says it publishes the battery state."},
            {"evidence",
             QJsonArray{QJsonObject{
                 {"file", kBattery}, {"line", 9}, {"end_line", 10}, {"quote", "BatteryMonitor"}}}}};
        content = json({{"descriptions", QJsonArray{item}}});
    }
    return stream ? FakeLlmServer::stream(content, 24) : FakeLlmServer::chat(content);
}

} // namespace

/// A Document shown in a suggestions panel and driven by a controller, with its log kept.
struct Rig
{
    Document doc;
    SuggestionModel model{&doc};
    SuggestionPanel panel;
    SuggestionController controller{&doc, &panel};
    QStringList log;

    explicit Rig(const Recovery *recovery = nullptr)
    {
        if (recovery)
            doc.setRecovery(*recovery);
        panel.setModel(&model);
        QObject::connect(&controller, &SuggestionController::logged, &controller,
                         [this](const QString &l) { log << l; });
    }
};

class TestSuggestionFlow : public QObject
{
    Q_OBJECT
private:
    test::SuggestionFixture m_fixture;
    const Recovery &m_recovery = m_fixture.recovery;
    const SuggestionReport &m_deterministic = m_fixture.deterministic;

    void load(Document &doc) { m_fixture.load(doc); }
    const Suggestion &first(const Document &doc, Suggestion::Kind kind)
    {
        return test::firstOf(doc, kind);
    }
    void clearDecisions() { QFile::remove(ProjectFile::locate(exampleWorkspace())); }
    void configureLlm(const QString &endpoint, bool use)
    {
        AppSettings settings;
        LlmSettings llm;
        llm.endpoint = endpoint;
        llm.model = QStringLiteral("fake-model");
        llm.requestTimeoutMs = 20000;
        settings.setLlmSettings(llm);
        settings.setUseLlm(use);
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(m_fixture.setUp()); }

    void init()
    {
        clearDecisions();
        configureLlm(QString(), false);
    }

    void acceptDescriptionChangesTheNode()
    {
        Document doc;
        load(doc);
        const Suggestion s = first(doc, Suggestion::Kind::NodeDescription);
        QCOMPARE(s.targetId, QStringLiteral("arc_1"));
        QVERIFY(doc.atomicNodes().node(QStringLiteral("arc_1"))->description.isEmpty());
        const Snapshot before = snapshot(doc);
        QSignalSpy changed(&doc, &Document::changed);

        QVERIFY(doc.session()->acceptSuggestion(s.id));
        QCOMPARE(doc.atomicNodes().node(QStringLiteral("arc_1"))->description, s.value);
        QCOMPARE(doc.session()->suggestion(s.id)->status, Suggestion::Status::Accepted);
        QCOMPARE(test::changedIds(changed, DocumentChange::Node),
                 QStringList{QStringLiteral("arc_1")});
        QCOMPARE(test::changedIds(changed, DocumentChange::Suggestion), QStringList{s.id});
        QCOMPARE(test::changesOf(changed, DocumentChange::Decisions).size(), 1);
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(!doc.session()->acceptSuggestion(s.id)); // already accepted: nothing pushed
        QCOMPARE(doc.undoStack()->count(), 1);
        const Snapshot after = snapshot(doc);
        QVERIFY(after != before);

        doc.undoStack()->undo();
        QCOMPARE(describe(snapshot(doc)), describe(before));
        QVERIFY(snapshot(doc) == before);
        doc.undoStack()->redo();
        QVERIFY(snapshot(doc) == after);
    }

    void rejectChangesTheStatusOnly()
    {
        Document doc;
        load(doc);
        const Suggestion s = first(doc, Suggestion::Kind::NodeDescription);
        const Snapshot before = snapshot(doc);
        QSignalSpy changed(&doc, &Document::changed);
        QVERIFY(doc.session()->rejectSuggestion(s.id));
        const Snapshot after = snapshot(doc);
        QCOMPARE(after.descriptions, before.descriptions);
        QCOMPARE(after.groupings, before.groupings);
        QCOMPARE(test::changesOf(changed, DocumentChange::Node).size(), 0);
        QCOMPARE(doc.session()->suggestion(s.id)->status, Suggestion::Status::Rejected);
        QCOMPARE(after.decisions,
                 QStringList{QStringLiteral("node-description arc_1 %1 rejected").arg(s.value)});
        doc.undoStack()->undo();
        QVERIFY(snapshot(doc) == before);
        doc.undoStack()->redo();
        QVERIFY(snapshot(doc) == after);

        // Accepting what was rejected applies it; rejecting an accepted one takes it back.
        QVERIFY(doc.session()->acceptSuggestion(s.id));
        QCOMPARE(doc.atomicNodes().node(s.targetId)->description, s.value);
        QVERIFY(doc.session()->rejectSuggestion(s.id));
        QVERIFY(doc.atomicNodes().node(s.targetId)->description.isEmpty());
        QCOMPARE(doc.undoStack()->count(), 3);
        doc.undoStack()->undo();
        QCOMPARE(doc.atomicNodes().node(s.targetId)->description, s.value);
    }

    void groupingIsStoredWhenAccepted()
    {
        Document doc;
        load(doc);
        const Suggestion g = first(doc, Suggestion::Kind::SubsystemGrouping);
        QVERIFY(doc.session()->acceptedGroupings().isEmpty());
        const Snapshot before = snapshot(doc);
        QSignalSpy changed(&doc, &Document::changed);
        QVERIFY(doc.session()->acceptSuggestion(g.id));
        QCOMPARE(test::changesOf(changed, DocumentChange::Decisions).size(), 1);
        const QList<SubsystemGroup> expected{{QStringLiteral("mission"),
                                              {QStringLiteral("n2"), QStringLiteral("n4"),
                                               QStringLiteral("n6"), QStringLiteral("n7")},
                                              g.targetId}};
        QCOMPARE(doc.session()->acceptedGroupings(), expected);
        QVERIFY(!g.targetId.isEmpty());
        QVERIFY(doc.launchDependencies().instance(g.targetId)->parentId.isEmpty()); // a root
        QCOMPARE(snapshot(doc).descriptions, before.descriptions);
        doc.undoStack()->undo();
        QVERIFY(doc.session()->acceptedGroupings().isEmpty());
        QVERIFY(snapshot(doc) == before);
    }

    void acceptAllOfAKindIsOneUndoStep()
    {
        Document doc;
        load(doc);
        // One description decided on its own first: accept-all takes only the pending ones.
        const Suggestion rejected = first(doc, Suggestion::Kind::NodeDescription);
        QVERIFY(doc.session()->rejectSuggestion(rejected.id));
        const Snapshot before = snapshot(doc);
        QCOMPARE(doc.session()->acceptAllSuggestions(Suggestion::Kind::NodeDescription), 7);
        QCOMPARE(doc.undoStack()->count(), 2);
        const Snapshot after = snapshot(doc);
        for (const Suggestion &s : doc.session()->suggestions()) {
            if (s.id == rejected.id)
                QCOMPARE(s.status, Suggestion::Status::Rejected);
            else if (s.kind == Suggestion::Kind::NodeDescription) {
                QCOMPARE(s.status, Suggestion::Status::Accepted);
                QCOMPARE(doc.atomicNodes().node(s.targetId)->description, s.value);
            } else
                QCOMPARE(s.status, Suggestion::Status::Pending); // the grouping is another kind
        }
        QVERIFY(doc.atomicNodes().node(rejected.targetId)->description.isEmpty());
        QCOMPARE(doc.session()->acceptAllSuggestions(Suggestion::Kind::NodeDescription), 0);
        QCOMPARE(doc.undoStack()->count(), 2);

        doc.undoStack()->undo(); // one step takes back all seven
        QCOMPARE(describe(snapshot(doc)), describe(before));
        QVERIFY(snapshot(doc) == before);
        doc.undoStack()->redo();
        QVERIFY(snapshot(doc) == after);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.session()->decisions().size(), 0);
    }

    void runnerDeliversDeterministicSuggestions()
    {
        SuggestionRunner runner;
        QSignalSpy started(&runner, &SuggestionRunner::suggestionsStarted);
        QSignalSpy finished(&runner, &SuggestionRunner::suggestionsFinished);
        runner.run(exampleWorkspace(), m_recovery, {});
        QCOMPARE(started.size(), 1);
        QCOMPARE(started.at(0).at(0).toBool(), false);
        QVERIFY(runner.isRunning());
        QVERIFY(finished.wait(30000));
        QVERIFY(!runner.isRunning());
        const auto report = finished.at(0).at(0).value<SuggestionReport>();
        QCOMPARE(report.suggestions.size(), m_deterministic.suggestions.size());
        for (qsizetype i = 0; i < report.suggestions.size(); ++i) {
            QCOMPARE(report.suggestions[i].subjectKey(),
                     m_deterministic.suggestions[i].subjectKey());
            QCOMPARE(report.suggestions[i].value, m_deterministic.suggestions[i].value);
        }
        QVERIFY(report.errors.isEmpty());
        QVERIFY(!report.llmUsed);
    }

    void staleResultsAreDroppedAndCancelKeepsWhatArrived()
    {
        FakeLlmServer server;
        FakeResponse hang;
        hang.hang = true;
        server.setHandler([hang](const FakeRequest &) { return hang; });
        SuggestionRunner::Options slow;
        slow.useLlm = true;
        slow.llm.endpoint = server.endpoint();
        slow.llm.requestTimeoutMs = 30000;

        SuggestionRunner runner;
        QSignalSpy finished(&runner, &SuggestionRunner::suggestionsFinished);
        QSignalSpy canceled(&runner, &SuggestionRunner::suggestionsCanceled);
        runner.run(exampleWorkspace(), m_recovery, slow);
        QVERIFY(QTest::qWaitFor([&] { return server.requests().size() == 1; }, 20000));
        Recovery other = m_recovery;
        other.nodes.nodes.removeFirst(); // the second run has one node less
        runner.run(exampleWorkspace(), other, {});
        QCOMPARE(runner.generation(), 2);
        QVERIFY(finished.wait(30000));
        QTest::qWait(300); // the first run's late result must not arrive
        QCOMPARE(finished.size(), 1);
        QCOMPARE(canceled.size(), 0);
        const auto report = finished.at(0).at(0).value<SuggestionReport>();
        for (const Suggestion &s : report.suggestions)
            QVERIFY(s.targetId != QStringLiteral("arc_1"));

        // Cancel while the LLM is asked: the deterministic suggestions are kept.
        runner.run(exampleWorkspace(), m_recovery, slow);
        QVERIFY(QTest::qWaitFor([&] { return server.requests().size() >= 2; }, 20000));
        runner.cancel();
        QVERIFY(canceled.wait(15000));
        QCOMPARE(finished.size(), 1);
        const auto partial = canceled.at(0).at(0).value<SuggestionReport>();
        QCOMPARE(partial.suggestions.size(), 9);
        for (const Suggestion &s : partial.suggestions)
            QCOMPARE(s.origin.provider, QStringLiteral("deterministic"));
    }

    void llmRunThroughTheControllerOverHttp()
    {
        FakeLlmServer server;
        server.setHandler([](const FakeRequest &r) { return reply(r, true); });
        configureLlm(server.endpoint(), true);

        Rig rig(&m_recovery);
        auto &[doc, model, panel, controller, log] = rig;
        QSignalSpy progressed(controller.runner(), &SuggestionRunner::suggestionsProgressed);
        QSignalSpy finished(controller.runner(), &SuggestionRunner::suggestionsFinished);

        panel.runAction()->trigger();
        QVERIFY(panel.isRunning());
        QVERIFY(!panel.runAction()->isEnabled());
        QVERIFY(panel.cancelAction()->isEnabled());
        QVERIFY(finished.wait(60000));
        QVERIFY(!panel.isRunning());
        // Streamed characters arrived piece by piece while it ran (24-character SSE chunks).
        QList<qint64> describe;
        for (const QList<QVariant> &p : std::as_const(progressed))
            if (p.at(0).toString() == QLatin1String("describe_nodes"))
                describe << p.at(1).toLongLong();
        QVERIFY2(describe.size() > 3, qPrintable(QString::number(describe.size())));
        QVERIFY(*std::max_element(describe.cbegin(), describe.cend()) > 200);

        // Sent over HTTP with the key from the environment, and the reply shown as pending.
        QVERIFY(server.requests().size() >= 2);
        QCOMPARE(server.requests().first().headers.value("authorization"),
                 "Bearer " + kSecret.toUtf8());
        QCOMPARE(doc.session()->suggestions().size(), 10);
        const Suggestion &llm = doc.session()->suggestions().last();
        QCOMPARE(llm.origin.provider, QStringLiteral("llm:fake-model"));
        QCOMPARE(llm.targetId, QStringLiteral("arc_1"));
        QCOMPARE(llm.status, Suggestion::Status::Pending);
        QCOMPARE(model.rowCount(), 10);
        QCOMPARE(model.index(9, SuggestionModel::OriginColumn).data().toString(),
                 QStringLiteral("llm:fake-model"));
        QCOMPARE(panel.countsLabel()->text(),
                 QStringLiteral("10 pending · 0 accepted · 0 rejected"));
        QVERIFY2(log.contains(QStringLiteral("Suggestions: 10 new (9 descriptions, 1 grouping)")),
                 qPrintable(log.join('\n')));
        for (const QString &line : log)
            QVERIFY2(!line.contains(kSecret), qPrintable(line));

        // Accepting it through the panel changes the model; Undo takes it back.
        panel.selectSuggestion(llm.id);
        panel.resize(1100, 460);
        panel.show();
        test::saveScreenshot(panel, QStringLiteral("suggestions-fake-llm.png"));
        panel.acceptAction()->trigger();
        QCOMPARE(doc.atomicNodes().node(QStringLiteral("arc_1"))->description, llm.value);
        doc.undoStack()->undo();
        QVERIFY(doc.atomicNodes().node(QStringLiteral("arc_1"))->description.isEmpty());

        // The settings file holds the endpoint and the model, never the key.
        QSettings settings(QStringLiteral("rosarch"), QCoreApplication::applicationName());
        const QByteArray stored = test::readFile(settings.fileName());
        QVERIFY2(stored.contains("fake-model"), stored.constData());
        QVERIFY(!stored.contains(kSecret.toUtf8()));
    }

    void failingEndpointShowsTheErrorAndTheDeterministicSuggestions()
    {
        configureLlm(QStringLiteral("http://127.0.0.1:%1").arg(FakeLlmServer::closedPort()), true);
        Rig rig(&m_recovery);
        auto &[doc, model, panel, controller, log] = rig;
        QSignalSpy finished(controller.runner(), &SuggestionRunner::suggestionsFinished);
        controller.run();
        QVERIFY(finished.wait(30000));
        QCOMPARE(doc.session()->suggestions().size(), 9);
        for (const Suggestion &s : doc.session()->suggestions())
            QCOMPARE(s.origin.provider, QStringLiteral("deterministic"));
        QCOMPARE(model.rowCount(), 9);
        const QStringList errors = log.filter(QStringLiteral("the LLM failed"));
        QCOMPARE(errors.size(), 1);
        QVERIFY2(errors[0].contains(QStringLiteral("Cannot connect")), qPrintable(errors[0]));
        QCOMPARE(panel.progressLabel()->text(), QStringLiteral("The LLM failed; see the log"));
        panel.resize(1100, 460);
        panel.show();
        test::saveScreenshot(panel, QStringLiteral("suggestions-failed-llm.png"));
        QVERIFY(log.contains(QStringLiteral("Suggestions: 9 new (8 descriptions, 1 grouping)")));
    }

    void runWithoutAModelSaysWhatToDo()
    {
        Rig rig;
        auto &[doc, model, panel, controller, log] = rig;
        controller.run();
        QVERIFY(!controller.runner()->isRunning());
        QCOMPARE(log.size(), 1);
        QVERIFY(log[0].contains(QStringLiteral("open a workspace")));
    }

    void settingsEditorStoresTheChoice()
    {
        Rig rig;
        auto &[doc, model, panel, controller, log] = rig;
        controller.setSettingsEditor([](LlmSettings *s, bool *use) {
            s->endpoint = QStringLiteral("http://llm.example:8000/v1");
            s->model = QStringLiteral("llama3.1");
            s->temperature = 0.3;
            *use = true;
            return true;
        });
        panel.settingsAction()->trigger();
        const SuggestionRunner::Options options = controller.runOptions();
        QVERIFY(options.useLlm);
        QCOMPARE(options.llm.endpoint, QStringLiteral("http://llm.example:8000/v1"));
        QCOMPARE(options.llm.model, QStringLiteral("llama3.1"));
        QCOMPARE(options.llm.temperature, 0.3);
        QCOMPARE(log.size(), 1);
        QVERIFY(log[0].contains(QStringLiteral("key=set (hidden)")));
        QVERIFY(!log[0].contains(kSecret));
    }
};

QTEST_MAIN(TestSuggestionFlow)
#include "tst_suggestionflow.moc"
