// File > Export Architecture Site's worker: the site is written off the calling thread with
// progress, and a cancellation writes nothing.
#include "app/commands/siteexport.h"
#include "pipeline/recovery.h"
#include "support/testsupport.h"

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

class TestSiteExport : public QObject
{
    Q_OBJECT

    Recovery m_recovery;

    SiteOptions options(const QString &folder) const
    {
        SiteOptions o;
        o.workspace = QDir(QStringLiteral(ROSARCH_SOURCE_DIR))
                          .filePath(QStringLiteral("resources/example_ws"));
        o.siteFolder = folder;
        return o;
    }

private Q_SLOTS:
    void initTestCase() { m_recovery = recoverWorkspace(options({}).workspace); }

    void writesOffTheCallingThread()
    {
        QTemporaryDir dir;
        const QString folder = dir.filePath(QStringLiteral("site"));
        SiteExport job;
        QSignalSpy progress(&job, &SiteExport::progressed);
        QSignalSpy finished(&job, &SiteExport::finished);
        QVERIFY(job.start(m_recovery, {}, options(folder)));
        QVERIFY(!job.start(m_recovery, {}, options(folder))); // one at a time
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().at(0).toBool(), true);
        QVERIFY2(finished.first().at(1).toString().contains(QLatin1String("index.html")),
                 qPrintable(finished.first().at(1).toString()));
        QVERIFY(!progress.isEmpty());
        QCOMPARE(progress.last().at(0).toInt(), progress.last().at(1).toInt());
        QVERIFY(QFileInfo::exists(folder + QStringLiteral("/systems/robot.html")));
    }

    void cancelWritesNothing()
    {
        QTemporaryDir dir;
        const QString folder = dir.filePath(QStringLiteral("site"));
        SiteExport job;
        // Canceled from the worker at the first progress report: deterministic.
        connect(
            &job, &SiteExport::progressed, &job, [&job] { job.cancel(); }, Qt::DirectConnection);
        QSignalSpy finished(&job, &SiteExport::finished);
        QVERIFY(job.start(m_recovery, {}, options(folder)));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY(finished.first().at(1).toString().contains(QLatin1String("canceled")));
        QVERIFY(!QFileInfo::exists(folder));
    }

    void failureSaysWhy()
    {
        SiteExport job;
        QSignalSpy finished(&job, &SiteExport::finished);
        QVERIFY(job.start(m_recovery, {}, options(QStringLiteral("/proc/rosarch-site"))));
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY(finished.first().at(1).toString().contains(QLatin1String("Cannot create")));
    }
};

QTEST_GUILESS_MAIN(TestSiteExport)
#include "tst_siteexport.moc"
