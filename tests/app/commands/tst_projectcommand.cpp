// The project headless (blueprint §5): `recover --project` writes exactly what the corrected
// model gives (the expected artifacts of tests/data/project_corrections), the workspace's own
// rosarch.project.json applies by default, and `project check` lists orphaned entries with an
// exit code CI can use.
#include "support/testsupport.h"

#include <QDirIterator>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QString caseDir()
{
    return test::dataDir(QStringLiteral("project_corrections"));
}

QString projectFile()
{
    return QDir(caseDir()).filePath(QStringLiteral("rosarch.project.json"));
}

/// Every file of `expectedDir` is byte-identical in `outDir`.
void sameAsExpected(const QString &outDir, const QString &expectedDir)
{
    QDirIterator it(expectedDir, {QStringLiteral("*.json"), QStringLiteral("*.puml")}, QDir::Files,
                    QDirIterator::Subdirectories);
    int files = 0;
    while (it.hasNext()) {
        const QString rel = QDir(expectedDir).relativeFilePath(it.next());
        QVERIFY2(test::readFile(QDir(outDir).filePath(rel)) ==
                     test::readFile(QDir(expectedDir).filePath(rel)),
                 qPrintable(rel));
        ++files;
    }
    QVERIFY(files >= 9);
}

} // namespace

class TestProjectCommand : public QObject
{
    Q_OBJECT

private Q_SLOTS:
    void recoverAppliesTheGivenProject()
    {
        QTemporaryDir out;
        const test::Run run = test::runRosarch(
            {QStringLiteral("recover"), QDir(caseDir()).filePath(QStringLiteral("ws")),
             QStringLiteral("--out"), out.path(), QStringLiteral("--project"), projectFile()});
        QCOMPARE(run.exitCode, 0);
        QVERIFY2(run.out.contains(QLatin1String("Applied 14 accepted decisions and corrections")),
                 qPrintable(run.out));
        sameAsExpected(out.path(), QDir(caseDir()).filePath(QStringLiteral("corrected")));
    }

    void recoverAppliesTheWorkspacesOwnProjectUnlessTold()
    {
        QTemporaryDir ws;
        test::copyTree(QDir(caseDir()).filePath(QStringLiteral("ws")), ws.path());
        QVERIFY(QFile::copy(projectFile(),
                            QDir(ws.path()).filePath(QStringLiteral("rosarch.project.json"))));
        QTemporaryDir out;
        const test::Run run = test::runRosarch(
            {QStringLiteral("recover"), ws.path(), QStringLiteral("--out"), out.path()});
        QCOMPARE(run.exitCode, 0);
        sameAsExpected(out.path(), QDir(caseDir()).filePath(QStringLiteral("corrected")));
        const test::Run raw =
            test::runRosarch({QStringLiteral("recover"), ws.path(), QStringLiteral("--out"),
                              out.path(), QStringLiteral("--no-decisions")});
        QCOMPARE(raw.exitCode, 0);
        const QByteArray arch =
            test::readFile(QDir(out.path()).filePath(QStringLiteral("architecture.json")));
        QVERIFY(!arch.contains("provenance"));
        QVERIFY(arch.contains("safety_monitor"));
    }

    void orphanedEntriesAreReportedByRecoverAndCheck()
    {
        QTemporaryDir ws;
        test::copyTree(QDir(caseDir()).filePath(QStringLiteral("ws")), ws.path());
        const test::Run clean = test::runRosarch(
            {QStringLiteral("project"), QStringLiteral("check"), projectFile(), ws.path()});
        QCOMPARE(clean.exitCode, 0);
        QVERIFY2(clean.out.contains(QLatin1String("1 decisions and 13 corrections; 0 orphaned")),
                 qPrintable(clean.out));

        test::copyTree(QDir(caseDir()).filePath(QStringLiteral("change")), ws.path());
        const test::Run changed = test::runRosarch(
            {QStringLiteral("project"), QStringLiteral("check"), projectFile(), ws.path()});
        QCOMPARE(changed.exitCode, 1);
        QVERIFY2(changed.out.contains(QLatin1String("orphaned correction c1 (rename): nothing in "
                                                    "this recovery has the key "
                                                    "instance:src/cart_base/launch/"
                                                    "cart.launch.py|safety_monitor; it said: "
                                                    "safety_monitor")),
                 qPrintable(changed.out));
        QVERIFY(changed.out.contains(QLatin1String("orphaned correction c10 (group)")));
        QVERIFY(changed.out.contains(QLatin1String("2 orphaned")));

        QTemporaryDir out;
        const test::Run recover =
            test::runRosarch({QStringLiteral("recover"), ws.path(), QStringLiteral("--out"),
                              out.path(), QStringLiteral("--project"), projectFile()});
        QCOMPARE(recover.exitCode, 0);
        QVERIFY2(recover.err.contains(QLatin1String("warning: orphaned correction c1 (rename)")),
                 qPrintable(recover.err));
        sameAsExpected(out.path(),
                       QDir(caseDir()).filePath(QStringLiteral("corrected_after_change")));
    }

    void aBrokenProjectStopsWithAMessage()
    {
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("broken.json"));
        test::writeFile(file, "{\"version\": 99}");
        const test::Run check =
            test::runRosarch({QStringLiteral("project"), QStringLiteral("check"), file,
                              QDir(caseDir()).filePath(QStringLiteral("ws"))});
        QCOMPARE(check.exitCode, 3);
        QVERIFY2(check.err.contains(QLatin1String("newer rosarch")), qPrintable(check.err));
        QTemporaryDir out;
        const test::Run recover = test::runRosarch(
            {QStringLiteral("recover"), QDir(caseDir()).filePath(QStringLiteral("ws")),
             QStringLiteral("--out"), out.path(), QStringLiteral("--project"), file});
        QCOMPARE(recover.exitCode, 2);
        QVERIFY2(recover.err.contains(file), qPrintable(recover.err));
        QVERIFY(QDir(out.path()).isEmpty()); // nothing written
        const test::Run usage =
            test::runRosarch({QStringLiteral("project"), QStringLiteral("verify"), file});
        QCOMPARE(usage.exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestProjectCommand)
#include "tst_projectcommand.moc"
