// `rosarch check` end to end, with the real executable: exit codes, the baseline workflow,
// and SARIF output that the OASIS SARIF 2.1.0 schema accepts, checked by a real JSON-schema
// validator (scripts/fetch-sarif-schema.sh puts both in the build tree).
#include "testsupport.h"

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

/// Runs the schema validator on `files`; its exit code (0 valid) and output.
int validate(const QStringList &files, QString *output)
{
    const QDir sarif(QStringLiteral(ROSARCH_SARIF_DIR));
    QProcess node;
    node.start(QStringLiteral(ROSARCH_NODE),
               QStringList{QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                               .filePath(QStringLiteral("tests/support/validate-json-schema.cjs")),
                           sarif.filePath(QStringLiteral("json-schema")),
                           sarif.filePath(QStringLiteral("schema/sarif-2.1.0.json"))} +
                   files);
    if (!node.waitForFinished(60000))
        return -1;
    *output = QString::fromUtf8(node.readAllStandardOutput() + node.readAllStandardError());
    return node.exitStatus() == QProcess::NormalExit ? node.exitCode() : -2;
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
        // The fixture has warnings and notes but no error.
        Run r = runRosarch({QStringLiteral("check"), ws});
        QCOMPARE(r.exitCode, 0);
        QVERIFY(r.out.contains(QLatin1String("[qos-incompatible]")));
        QVERIFY(r.out.contains(QLatin1String("6 findings (0 errors, 5 warnings, 1 notes)")));
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
        QVERIFY(r.out.contains(QLatin1String("6 in the baseline; 0 fail the check")));
        // Another system has other findings: the old baseline does not cover them.
        r = runRosarch({QStringLiteral("check"), workspace(QStringLiteral("compose_system/ws")),
                        QStringLiteral("--fail-on"), QStringLiteral("warning"),
                        QStringLiteral("--baseline"), baseline});
        QCOMPARE(r.exitCode, 1);
    }

    void jsonAndJunit()
    {
        const QString ws = workspace(QStringLiteral("check_system/ws"));
        Run r = runRosarch(
            {QStringLiteral("check"), ws, QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(r.exitCode, 0);
        const QJsonObject root = QJsonDocument::fromJson(r.out.toUtf8()).object();
        QCOMPARE(root.value(QStringLiteral("findings")).toArray().size(), 6);
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
};

QTEST_GUILESS_MAIN(TestCheckCommand)
#include "tst_checkcommand.moc"
