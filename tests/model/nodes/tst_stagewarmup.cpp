// Stage 1's warm-up in an idle long-lived worker (NodeAnalyzer::warmUp): after a run that the
// stage's memo answered, it decodes what the next run after an edit reuses, so that the first
// edit reads nothing more from the cache's packs than later ones. Run to its end, stopped part
// way, or stopped at once by the next request, the edit gives exactly what a fresh run gives.
#include "cache/analysiscache.h"
#include "nodes/nodeanalyzer.h"
#include "pipeline/recovery.h"
#include "pipeline/stagesession.h"
#include "support/cacherecovery.h"
#include "support/cachetestcase.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QTemporaryDir>
#include <QtTest>

#include <atomic>

using namespace rosarch;

namespace {

const QString kRectifier = QStringLiteral("src/vision/src/rectifier.cpp");

void prependComment(const QString &file, int n)
{
    QByteArray source = test::readFile(file);
    source.prepend("// edit " + QByteArray::number(n) + '\n');
    test::writeFile(file, source);
}

/// Entries read from the packs (hits that were not kept in memory).
int readFromPacks(const AnalysisCache::Statistics &s)
{
    return s.hits - s.kept;
}

} // namespace

class TestStageWarmUp : public QObject
{
    Q_OBJECT

    QTemporaryDir m_temp;
    QString m_ws;
    QString m_cache;

    /// A cache that a cold run filled, opened again: a new worker's warm start.
    void fillCache()
    {
        AnalysisCache cold(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        test::recoverWith(m_ws, &cold);
    }

    /// The first edit after a warm start, with the warm-up stopped after `polls` of its
    /// cancellation checks (-1: never stopped); how many entries it read from the packs.
    int firstEdit(int polls)
    {
        fillCache();
        AnalysisCache warm(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        test::recoverWith(m_ws, &warm);
        if (polls != 0) {
            std::atomic<int> left{polls};
            StageControl control;
            control.cache = &warm;
            control.canceled = [&] { return polls > 0 && left.fetch_sub(1) <= 0; };
            NodeAnalyzer::warmUp(WorkspaceScanner::scan(m_ws, {}), control);
        }
        prependComment(m_ws + QLatin1Char('/') + kRectifier, polls);
        const AnalysisCache::Statistics before = warm.statistics();
        const Recovery edited = test::recoverWith(m_ws, &warm);
        const Recovery fresh = test::recoverUncached(m_ws);
        if (!(edited == fresh))
            return -1;
        return readFromPacks(warm.statistics()) - readFromPacks(before);
    }

private Q_SLOTS:
    void init()
    {
        QVERIFY(m_temp.isValid());
        test::freshCacheCase(m_temp, &m_ws, &m_cache);
    }

    void theFirstEditAfterAWarmUpReadsLessFromThePacks()
    {
        const int withWarmUp = firstEdit(-1);
        QVERIFY(withWarmUp >= 0); // -1: the edit's result differs from a fresh run's
        init();
        const int without = firstEdit(0);
        QVERIFY(without >= 0);
        // Without it, the unchanged files' entries are read from the packs; with it, all came
        // from memory.
        QVERIFY(without > 0);
        QCOMPARE(withWarmUp, 0);
    }

    void aStoppedWarmUpChangesNoResult_data()
    {
        QTest::addColumn<int>("polls");
        for (int polls : {1, 2, 4, 8, 16})
            QTest::addRow("after %d", polls) << polls;
    }

    void aStoppedWarmUpChangesNoResult()
    {
        QFETCH(int, polls);
        QVERIFY(firstEdit(polls) >= 0);
    }

    void aLongLivedWorkerWarmsUpBetweenRuns()
    {
        // The worker's cache is in m_cache (the worker inherits the environment).
        qputenv("ROSARCH_CACHE_DIR", QFile::encodeName(m_cache));
        fillCache();
        StageSession session;
        const StageProcess::Result warm = session.recover(m_ws, {}, {});
        QVERIFY2(warm.error.isEmpty(), qPrintable(warm.error));
        // At once: the request stops the warm-up just begun.
        prependComment(m_ws + QLatin1Char('/') + kRectifier, 1);
        StageProcess::Result r = session.recover(m_ws, {}, {});
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QVERIFY(r.recovery == test::recoverUncached(m_ws));
        // After a pause the warm-up has had time for (some or all of) its work.
        for (int edit = 2; edit < 5; ++edit) {
            QTest::qWait(300 * (edit - 1));
            prependComment(m_ws + QLatin1Char('/') + kRectifier, edit);
            r = session.recover(m_ws, {}, {});
            QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
            QVERIFY(r.recovery == test::recoverUncached(m_ws));
        }
        QCOMPARE(session.workersStarted(), 1);
        qunsetenv("ROSARCH_CACHE_DIR");
    }
};

QTEST_GUILESS_MAIN(TestStageWarmUp)
#include "tst_stagewarmup.moc"
