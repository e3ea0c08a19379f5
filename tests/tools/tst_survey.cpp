// rosarch-survey on fixture workspaces: the counts it prints are what the analyzers find, and
// --dump lists the classes, ports and launch actions themselves.
#include "support/testsupport.h"

#include <QProcess>
#include <QtTest>

namespace {

struct Survey
{
    int exitCode = -1;
    QString out;
};

Survey survey(const QStringList &args)
{
    QProcess p;
    p.start(QStringLiteral(ROSARCH_SURVEY), args);
    Survey s;
    if (!p.waitForFinished(120000))
        return s;
    s.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    s.out = QString::fromUtf8(p.readAllStandardOutput());
    return s;
}

} // namespace

class TestSurvey : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void nodesCountsPerLanguage()
    {
        const Survey s = survey(
            {QStringLiteral("nodes"), rosarch::test::dataDir(QStringLiteral("py_basic/ws"))});
        QCOMPARE(s.exitCode, 0);
        QVERIFY2(s.out.contains(QLatin1String("python: 5 node classes")), qPrintable(s.out));
        QVERIFY2(s.out.contains(QLatin1String("c++: 0 node classes")), qPrintable(s.out));

        const Survey dump =
            survey({QStringLiteral("nodes"), rosarch::test::dataDir(QStringLiteral("cpp_basic/ws")),
                    QStringLiteral("--dump")});
        QCOMPARE(dump.exitCode, 0);
        QVERIFY2(dump.out.contains(QLatin1String("Talker [demo_cpp]")), qPrintable(dump.out));
        QVERIFY2(dump.out.contains(QLatin1String("publisher ")), qPrintable(dump.out));
    }

    void launchFilesOfEveryFormat()
    {
        const Survey s = survey({QStringLiteral("launch"),
                                 rosarch::test::dataDir(QStringLiteral("launch_formats")),
                                 QStringLiteral("--dump")});
        QCOMPARE(s.exitCode, 0);
        for (const char *format : {"files python ", "files xml ", "files yaml "})
            QVERIFY2(s.out.contains(QLatin1String(format)), qPrintable(s.out));
        QVERIFY2(s.out.contains(QLatin1String("kind Node ")), qPrintable(s.out));
        QVERIFY2(s.out.contains(QLatin1String("== ")), qPrintable(s.out));
    }

    void badArgumentsAreUsageErrors()
    {
        QCOMPARE(survey({}).exitCode, 2);
        QCOMPARE(survey({QStringLiteral("nodes"), QStringLiteral("/no/such/folder")}).exitCode, 2);
        QCOMPARE(survey({QStringLiteral("sideways"), QStringLiteral("/tmp")}).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestSurvey)
#include "tst_survey.moc"
