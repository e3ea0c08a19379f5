// rosarch-perfbench on a small fixture: it runs every case and reports them (the figures
// themselves are measurements, not checked here).
#include "testsupport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

class TestPerfBench : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void reportsEveryCase()
    {
        QProcess p;
        p.start(QStringLiteral(ROSARCH_PERFBENCH),
                {rosarch::test::dataDir(QStringLiteral("compose_system/ws")),
                 QStringLiteral("--runs"), QStringLiteral("1"), QStringLiteral("--json")});
        QVERIFY(p.waitForFinished(300000));
        QCOMPARE(p.exitCode(), 0);
        const QJsonObject report = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
        QCOMPARE(report.value(QStringLiteral("baseline"))
                     .toObject()
                     .value(QStringLiteral("cpp_files"))
                     .toInt(),
                 3);
        QCOMPARE(report.value(QStringLiteral("baseline"))
                     .toObject()
                     .value(QStringLiteral("python_files"))
                     .toInt(),
                 4);
        QVERIFY(report.value(QStringLiteral("edited_file")).toString().endsWith(u".cpp"));
        QStringList cases;
        for (const QJsonValue &v : report.value(QStringLiteral("cases")).toArray()) {
            const QJsonObject c = v.toObject();
            cases << c.value(QStringLiteral("case")).toString() + QLatin1Char('/') +
                         c.value(QStringLiteral("path")).toString();
            QCOMPARE(c.value(QStringLiteral("runs_ms")).toArray().size(), 1);
            QVERIFY(c.value(QStringLiteral("peak_rss_kb")).toInteger() > 0);
        }
        QCOMPARE(cases, (QStringList{
                            QStringLiteral("no-cache/worker"),
                            QStringLiteral("no-cache/in-process"),
                            QStringLiteral("cold/worker"),
                            QStringLiteral("cold/in-process"),
                            QStringLiteral("warm/worker"),
                            QStringLiteral("warm/in-process"),
                            QStringLiteral("one-file-edit/worker"),
                            QStringLiteral("one-file-edit/in-process"),
                            QStringLiteral("warm/gui-session"),
                            QStringLiteral("one-file-edit/gui-session"),
                        }));
        QVERIFY(report.value(QStringLiteral("peak_rss_kb")).toInteger() > 0);
    }

    void refusesWhatIsNotAFolder()
    {
        QProcess p;
        p.start(QStringLiteral(ROSARCH_PERFBENCH), {QStringLiteral("/no/such/folder")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 2);
        QVERIFY(p.readAllStandardError().contains("Not a folder"));
    }
};

QTEST_GUILESS_MAIN(TestPerfBench)
#include "tst_perfbench.moc"
