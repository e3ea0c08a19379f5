// `rosarch check` end to end, with the real executable: exit codes, the baseline workflow,
// and SARIF output that the OASIS SARIF 2.1.0 schema accepts, checked by a real JSON-schema
// validator (scripts/fetch-sarif-schema.sh puts both in the build tree).
#include "support/jsonschemacheck.h"
#include "support/testsupport.h"

#include <QCryptographicHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QXmlStreamReader>
#include <QtTest>

namespace {
using rosarch::test::Run;
using rosarch::test::runRosarch;

QString workspace(const QString &name)
{
    return rosarch::test::dataDir(name);
}

/// Runs the schema validator on `files` against `schema` (default: SARIF 2.1.0); its exit code
/// (0 valid) and output.
int validate(const QStringList &files, QString *output, const QString &schema = {})
{
    return rosarch::test::validateJsonSchema(
        schema.isEmpty() ? QDir(QStringLiteral(ROSARCH_SARIF_DIR))
                               .filePath(QStringLiteral("schema/sarif-2.1.0.json"))
                         : schema,
        files, output);
}
} // namespace

class TestCheckCommand : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QVERIFY2(QFileInfo::exists(QStringLiteral(ROSARCH_SARIF_DIR "/schema/sarif-2.1.0.json")),
                 "the SARIF schema is missing: run scripts/fetch-sarif-schema.sh build/_sarif "
                 "(./setup.sh does)");
        QVERIFY2(QFileInfo(QStringLiteral(ROSARCH_NODE)).isExecutable(),
                 "nodejs is missing (./setup.sh installs it)");
    }

    void exitCodesFollowFailOn()
    {
        const QString ws = workspace(QStringLiteral("check_system/ws"));
        // The fixture has warnings but no error and no note.
        Run r = runRosarch({QStringLiteral("check"), ws});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QLatin1String("[qos-incompatible]")));
        QVERIFY(r.out.contains(QLatin1String("5 findings (0 errors, 5 warnings, 0 notes)")));
        r = runRosarch(
            {QStringLiteral("check"), ws, QStringLiteral("--fail-on"), QStringLiteral("warning")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.contains(QLatin1String("5 fail the check")));
        r = runRosarch(
            {QStringLiteral("check"), ws, QStringLiteral("--fail-on"), QStringLiteral("info")});
        QCOMPARE(r.exitCode, 1);
        r = runRosarch(
            {QStringLiteral("check"), ws, QStringLiteral("--fail-on"), QStringLiteral("never")});
        QCOMPARE(r.exitCode, 0);
    }

    void usageAndFileErrors()
    {
        const QString ws = workspace(QStringLiteral("check_system/ws"));
        Run r = runRosarch(
            {QStringLiteral("check"), ws, QStringLiteral("--format"), QStringLiteral("xml")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QLatin1String("--format must be")));
        r = runRosarch({QStringLiteral("check")});
        QCOMPARE(r.exitCode, 2);
        r = runRosarch({QStringLiteral("check"), QStringLiteral("/no/such/folder")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY(r.err.contains(QLatin1String("Not a folder")));
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--baseline"),
                        QStringLiteral("/no/such/baseline.json")});
        QCOMPARE(r.exitCode, 3);
        QTemporaryDir dir;
        const QString broken = dir.filePath(QStringLiteral("broken.json"));
        rosarch::test::writeFile(broken, "{\"no\": \"findings\"}");
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--baseline"), broken});
        QCOMPARE(r.exitCode, 3);
        QVERIFY(r.err.contains(QLatin1String("cannot be used")));
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--output"),
                        QStringLiteral("/no/such/folder/report.txt")});
        QCOMPARE(r.exitCode, 3);
    }

    void baselineLetsOnlyNewFindingsFail()
    {
        QTemporaryDir dir;
        const QString ws = workspace(QStringLiteral("check_system/ws"));
        const QString baseline = dir.filePath(QStringLiteral("baseline.json"));
        Run r =
            runRosarch({QStringLiteral("check"), ws, QStringLiteral("--fail-on"),
                        QStringLiteral("warning"), QStringLiteral("--write-baseline"), baseline});
        QCOMPARE(r.exitCode, 1);
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--fail-on"),
                        QStringLiteral("warning"), QStringLiteral("--baseline"), baseline});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QLatin1String("5 in the baseline; 0 fail the check")));
        // Another system has other findings: the old baseline does not cover them.
        r = runRosarch({QStringLiteral("check"), workspace(QStringLiteral("compose_system/ws")),
                        QStringLiteral("--fail-on"), QStringLiteral("warning"),
                        QStringLiteral("--baseline"), baseline});
        QCOMPARE(r.exitCode, 1);
    }

    void acceptedFindingsAndPerSystemKeysAreKnown()
    {
        // check_roots: the planner's unpublished /map (and its misspelt /odom_raws) is one
        // finding seen in two systems.
        QTemporaryDir dir;
        const QString ws = workspace(QStringLiteral("check_roots/ws"));
        const QString report = dir.filePath(QStringLiteral("report.json"));
        Run r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--no-decisions"),
                            QStringLiteral("--fail-on"), QStringLiteral("warning"),
                            QStringLiteral("--format"), QStringLiteral("json"),
                            QStringLiteral("--output"), report});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains(QLatin1String("3 findings; 0 in the baseline; 3 fail")),
                 qPrintable(r.err));
        const QJsonArray findings = QJsonDocument::fromJson(rosarch::test::readFile(report))
                                        .object()[QLatin1String("findings")]
                                        .toArray();
        QJsonArray accepted;
        for (const QJsonValue &f : findings) {
            const QJsonObject o = f.toObject();
            if (o[QLatin1String("message")].toString().startsWith(QLatin1String("/planner")))
                QCOMPARE(o[QLatin1String("contexts")].toArray().size(), 2);
            if (o[QLatin1String("severity")].toString() == QLatin1String("warning"))
                accepted.append(QJsonObject{{QStringLiteral("key"), o[QLatin1String("key")]},
                                            {QStringLiteral("status"), QStringLiteral("accepted")},
                                            {QStringLiteral("reason"), QStringLiteral("a bag")}});
        }
        QCOMPARE(accepted.size(), 3);
        // Accepted in the project: known, reported, never failing.
        const QString project = dir.filePath(QStringLiteral("rosarch.project.json"));
        rosarch::test::writeFile(project,
                                 QJsonDocument(QJsonObject{{QStringLiteral("version"), 2},
                                                           {QStringLiteral("workspace"), ws},
                                                           {QStringLiteral("findings"), accepted}})
                                     .toJson());
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--project"), project,
                        QStringLiteral("--fail-on"), QStringLiteral("warning")});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains(QLatin1String("3 in the baseline; 0 fail the check")),
                 qPrintable(r.out));
        QVERIFY(r.out.contains(QLatin1String("seen in 2 systems")));
        // A baseline written before the merge names the finding by one system's key.
        const QString code = QStringLiteral("topic-unpublished");
        const QString old =
            code + QStringLiteral(":") +
            QString::fromLatin1(
                QCryptographicHash::hash(
                    (code + QStringLiteral("\nsrc/rover/rover/planner.py\n/planner "
                                           "subscribes to /map, which no node started by "
                                           "src/rover/launch/sim.launch.py publishes. "
                                           "src/rover/launch/nav.launch.py:8 remaps it "
                                           "(map:=/slam/map) where it starts a node of the "
                                           "same class; src/rover/launch/planning.launch.py "
                                           "starts this one without that remap."))
                        .toUtf8(),
                    QCryptographicHash::Sha1)
                    .toHex()
                    .left(16));
        const QString baseline = dir.filePath(QStringLiteral("old-baseline.txt"));
        rosarch::test::writeFile(baseline, old.toUtf8() + '\n');
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--no-decisions"),
                        QStringLiteral("--baseline"), baseline});
        QVERIFY2(r.out.contains(QLatin1String("1 in the baseline")), qPrintable(r.out));
    }

    void expectedExternalsOfTheProjectAreNoFindings()
    {
        // check_roots: the planner's /map comes from a map server outside the workspace.
        QTemporaryDir dir;
        const QString ws = workspace(QStringLiteral("check_roots/ws"));
        Run r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--no-decisions")});
        QVERIFY2(r.out.contains(QLatin1String("subscribes to /map,")), qPrintable(r.out));
        const QString project = dir.filePath(QStringLiteral("rosarch.project.json"));
        rosarch::test::writeFile(
            project,
            QJsonDocument(
                QJsonObject{{QStringLiteral("version"), 3},
                            {QStringLiteral("workspace"), ws},
                            {QStringLiteral("externals"),
                             QJsonArray{QJsonObject{
                                 {QStringLiteral("name"), QStringLiteral("/map")},
                                 {QStringLiteral("direction"), QStringLiteral("input")},
                                 {QStringLiteral("reason"), QStringLiteral("map server")}}}}})
                .toJson());
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--project"), project});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(!r.out.contains(QLatin1String("subscribes to /map,")), qPrintable(r.out));
    }

    void jsonAndJunit()
    {
        const QString ws = workspace(QStringLiteral("check_system/ws"));
        Run r = runRosarch(
            {QStringLiteral("check"), ws, QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(root.value(QStringLiteral("findings")).toArray().size(), 5);
        QCOMPARE(root.value(QStringLiteral("summary")).toObject().value(QStringLiteral("warnings")),
                 5);
        r = runRosarch({QStringLiteral("check"), ws, QStringLiteral("--format"),
                        QStringLiteral("junit"), QStringLiteral("--fail-on"),
                        QStringLiteral("warning")});
        QCOMPARE(r.exitCode, 1);
        QXmlStreamReader xml(r.out);
        int failures = 0;
        while (!xml.atEnd())
            if (xml.readNext() == QXmlStreamReader::StartElement &&
                xml.name() == QLatin1String("failure"))
                ++failures;
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QCOMPARE(failures, 5);
    }

    void sarifValidatesAgainstTheSchema()
    {
        QTemporaryDir dir;
        QStringList files;
        for (const QString &ws :
             {QStringLiteral("check_system/ws"), QStringLiteral("compose_system/ws"),
              QStringLiteral("example_ws")}) {
            const QString file = dir.filePath(
                QString(ws).replace(QLatin1Char('/'), QLatin1Char('_')) + QStringLiteral(".sarif"));
            const Run r =
                runRosarch({QStringLiteral("check"), workspace(ws), QStringLiteral("--format"),
                            QStringLiteral("sarif"), QStringLiteral("--output"), file,
                            QStringLiteral("--fail-on"), QStringLiteral("never")});
            QCOMPARE(r.exitCode, 0);
            files << file;
        }
        // Findings merged across roots carry their systems, and the schema checks those too.
        QVERIFY(rosarch::test::readFile(files.first()).contains("\"contexts\""));
        QString output;
        QCOMPARE(validate(files, &output), 0);
        // The validator is not a yes-man: a wrong level is caught.
        QByteArray bad = rosarch::test::readFile(files.first());
        bad.replace("\"level\": \"warning\"", "\"level\": \"severe\"");
        const QString badFile = dir.filePath(QStringLiteral("bad.sarif"));
        rosarch::test::writeFile(badFile, bad);
        QCOMPARE(validate({badFile}, &output), 1);
        QVERIFY2(output.contains(QLatin1String("level")), qPrintable(output));
    }

    void diagnosticsJsonValidatesAgainstItsSchema()
    {
        QTemporaryDir dir;
        QStringList files;
        for (const QString &ws :
             {QStringLiteral("check_system/ws"), QStringLiteral("compose_system/ws"),
              QStringLiteral("cpp_syntax_error")}) {
            const QString out =
                dir.filePath(QString(ws).replace(QLatin1Char('/'), QLatin1Char('_')));
            const Run r =
                runRosarch({QStringLiteral("recover"), workspace(ws), QStringLiteral("--out"), out,
                            QStringLiteral("--no-decisions")});
            QVERIFY2(r.exitCode == 0 || r.exitCode == 1, qPrintable(r.err));
            files << QDir(out).filePath(QStringLiteral("diagnostics.json"));
        }
        // The sample covers merged findings (contexts) and related places.
        const QByteArray first = rosarch::test::readFile(files.first());
        QVERIFY(first.contains("\"contexts\""));
        QVERIFY(first.contains("\"related\""));
        const QString schema = QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                                   .filePath(QStringLiteral("schemas/diagnostics.schema.json"));
        QString output;
        QVERIFY2(validate(files, &output, schema) == 0, qPrintable(output));
        // A finding with an unknown severity is caught.
        QByteArray bad = first;
        bad.replace("\"severity\": \"warning\"", "\"severity\": \"severe\"");
        const QString badFile = dir.filePath(QStringLiteral("bad.json"));
        rosarch::test::writeFile(badFile, bad);
        QCOMPARE(validate({badFile}, &output, schema), 1);
    }
};

QTEST_GUILESS_MAIN(TestCheckCommand)
#include "tst_checkcommand.moc"
