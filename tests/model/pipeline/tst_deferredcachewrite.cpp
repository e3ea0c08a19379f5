// An in-process recovery does not wait for its cache packs (DeferredCacheWrite): it leaves
// them to a thread of its own, whose pack is complete once written (or once the process has
// ended), so that the next run is warm; the result is the same as without the cache; a canceled
// run and a caller's own cache are handled as before; the worker's deferral is left alone, and
// its pack has stage 2's memo, encoded on a pool thread (AnalysisCache::finishStores); a stage
// called on its own without a cache does not use the process's.
#include "cache/analysiscache.h"
#include "nodes/cpp/cppnodeanalyzer.h"
#include "pipeline/deferredcachewrite.h"
#include "pipeline/recovery.h"
#include "pipeline/stageprocess.h"
#include "pipeline/workerprocess.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <memory>

using namespace rosarch;

namespace {

QString workspace()
{
    return test::dataDir(QStringLiteral("compose_system/ws"));
}

/// The packs in a cache root (`<root>/analysis/<build>/*.pack`), by name.
QStringList packsIn(const QString &root)
{
    QStringList packs;
    const QDir analysis(root + QStringLiteral("/analysis"));
    for (const QString &build : analysis.entryList(QDir::Dirs | QDir::NoDotAndDotDot))
        for (const QString &pack :
             QDir(analysis.filePath(build)).entryList({QStringLiteral("*.pack")}, QDir::Files))
            packs.append(build + QLatin1Char('/') + pack);
    packs.sort();
    return packs;
}

Recovery uncached(const QString &root)
{
    AnalysisCache off{QString()};
    StageControl control;
    control.cache = &off;
    return recoverWorkspace(root, {}, control);
}

} // namespace

class TestDeferredCacheWrite : public QObject
{
    Q_OBJECT

    QTemporaryDir m_cacheRoot;

private Q_SLOTS:
    void initTestCase()
    {
        // The shared cache, in a folder of this test (read once, when it is first used).
        QVERIFY(m_cacheRoot.isValid());
        qputenv("ROSARCH_NO_CACHE", "0");
        qputenv("ROSARCH_CACHE_DIR", m_cacheRoot.path().toUtf8());
        QVERIFY(AnalysisCache::shared().isEnabled());
        QCOMPARE(AnalysisCache::shared().directory().left(m_cacheRoot.path().size()),
                 m_cacheRoot.path());
    }

    void theRunLeavesItsPackToAThreadAndTheNextRunIsWarm()
    {
        AnalysisCache &cache = AnalysisCache::shared();
        const Recovery expected = uncached(workspace());
        QVERIFY(!expected.nodes.nodes.isEmpty());
        QVERIFY(packsIn(m_cacheRoot.path()).isEmpty());

        const AnalysisCache::Statistics before = cache.statistics();
        const Recovery cold = recoverWorkspace(workspace());
        QVERIFY(cold == expected);
        QVERIFY(cache.statistics().stores > before.stores);
        QVERIFY(!cache.defersFlush()); // deferral ends with the run
        DeferredCacheWrite::waitForWrites();
        const QStringList packs = packsIn(m_cacheRoot.path());
        QCOMPARE(packs.size(), 1); // stages 1 and 2 in one pack, written after the run

        // Warm: every result comes from the pack, nothing new is stored or written.
        const AnalysisCache::Statistics cold1 = cache.statistics();
        const Recovery warm = recoverWorkspace(workspace());
        QVERIFY(warm == expected);
        const AnalysisCache::Statistics warm1 = cache.statistics();
        QVERIFY(warm1.hits > cold1.hits);
        QCOMPARE(warm1.misses, cold1.misses);
        QCOMPARE(warm1.stores, cold1.stores);
        DeferredCacheWrite::waitForWrites();
        QCOMPARE(packsIn(m_cacheRoot.path()), packs);
        QVERIFY(!cache.takeProblem());
    }

    void aCanceledRunStillWritesWhatItStoredAndDefersNoMore_data()
    {
        QTest::addColumn<int>("after");
        for (int after : {0, 2, 5, 20})
            QTest::addRow("after %d polls", after) << after;
    }
    void aCanceledRunStillWritesWhatItStoredAndDefersNoMore()
    {
        QFETCH(int, after);
        const QString root = test::dataDir(QStringLiteral("launch_constructs/ws"));
        auto polls = std::make_shared<std::atomic<int>>(0);
        StageControl control;
        control.canceled = [polls, after] { return polls->fetch_add(1) >= after; };
        const Recovery canceled = recoverWorkspace(root, {}, control);
        // Canceled, unless the run asked fewer times than that: the rows before left the memos
        // of all three stages in the shared cache.
        QVERIFY(canceled.nodes.canceled || canceled.launch.canceled ||
                canceled.architecture.canceled || polls->load() <= after);
        QVERIFY(!AnalysisCache::shared().defersFlush());
        DeferredCacheWrite::waitForWrites();
        // What the canceled run stored serves the next one, which gives the whole result.
        QVERIFY(recoverWorkspace(root) == uncached(root));
        DeferredCacheWrite::waitForWrites();
    }

    void aCacheTheCallerOwnsIsWrittenAtOnce()
    {
        QTemporaryDir root;
        QVERIFY(root.isValid());
        {
            AnalysisCache own(root.path(), AnalysisCache::kDefaultMaxBytes, 0);
            StageControl control;
            control.cache = &own;
            QVERIFY(recoverWorkspace(workspace(), {}, control) == uncached(workspace()));
            QVERIFY(!own.defersFlush());
            QCOMPARE(packsIn(root.path()).size(), 3); // each stage's, as before
        }                                             // and nothing is left to write after it went
        QCOMPARE(packsIn(root.path()).size(), 3);
    }

    void aCacheThatDefersAlreadyIsLeftDeferring()
    {
        AnalysisCache &cache = AnalysisCache::shared();
        cache.setDeferFlush(true); // what the worker does: it writes after its reply
        {
            const DeferredCacheWrite run(cache);
        }
        QVERIFY(cache.defersFlush());
        cache.setDeferFlush(false);
    }

    void theWorkersPackHoldsStageTwosMemoEncodedAside()
    {
        // The worker encodes stage 2's memo on a pool thread and writes its pack after its
        // reply: the pack has it, so that a second worker stores (and writes) nothing.
        const QString root = test::dataDir(QStringLiteral("launch_formats/ws"));
        const QStringList before = packsIn(m_cacheRoot.path());
        const StageProcess::Result cold = StageProcess::recover(root, {}, {}, {});
        QVERIFY2(cold.error.isEmpty(), qPrintable(cold.error));
        WorkerProcess::waitForReleased();
        const QStringList after = packsIn(m_cacheRoot.path());
        QCOMPARE(after.size(), before.size() + 1);
        const StageProcess::Result warm = StageProcess::recover(root, {}, {}, {});
        QVERIFY2(warm.error.isEmpty(), qPrintable(warm.error));
        WorkerProcess::waitForReleased();
        QCOMPARE(packsIn(m_cacheRoot.path()), after);
        QVERIFY(warm.recovery == cold.recovery);
        QVERIFY(cold.recovery == uncached(root));
    }

    void theCppFactsAreInThePackThoughEncodedAfterTheFiles()
    {
        // Stage 1 encodes the facts of the C++ files it parsed once every file is done
        // (AnalysisCache::storeLater): the pack written after the run has them all, so that a
        // cache reading it parses no C++ file again and stores nothing.
        const QString root = test::dataDir(QStringLiteral("cpp_helpers/ws"));
        const Recovery cold = recoverWorkspace(root);
        QVERIFY(!cold.nodes.nodes.isEmpty());
        DeferredCacheWrite::waitForWrites();
        AnalysisCache again(AnalysisCache::defaultRoot(), AnalysisCache::kDefaultMaxBytes, 0);
        StageControl control;
        control.cache = &again;
        const Workspace ws = WorkspaceScanner::scan(root, control);
        const CppNodeAnalyzer analyzer(ws);
        const LanguageAnalysis analysis = analyzer.analyze(control);
        QVERIFY(!analysis.nodes.isEmpty());
        QVERIFY(again.statistics().hits > 0);
        QCOMPARE(again.statistics().misses, 0);
        QCOMPARE(again.statistics().stores, 0);
    }

    void aStageGivenNoCacheLeavesTheProcesssCacheAlone()
    {
        // Only the pipeline's entry points give the stages the process's cache: a stage called
        // on its own without one neither looks anything up in it nor stores anything there.
        AnalysisCache::finishStores();
        DeferredCacheWrite::waitForWrites();
        AnalysisCache &shared = AnalysisCache::shared();
        QVERIFY(shared.isEnabled());
        const AnalysisCache::Statistics before = shared.statistics();
        const Workspace ws =
            WorkspaceScanner::scan(test::dataDir(QStringLiteral("cpp_helpers/ws")));
        const LanguageAnalysis analysis = CppNodeAnalyzer(ws).analyze();
        QVERIFY(!analysis.nodes.isEmpty());
        const AnalysisCache::Statistics after = shared.statistics();
        QCOMPARE(after.hits, before.hits);
        QCOMPARE(after.misses, before.misses);
        QCOMPARE(after.stores, before.stores);
        QVERIFY(!AnalysisCache::of(StageControl()).isEnabled());
        StageControl control;
        control.cache = &shared;
        QCOMPARE(&AnalysisCache::of(control), &shared);
    }

    void aHeadlessRunLeavesACompleteCacheWhenItExits()
    {
        QTemporaryDir root;
        QTemporaryDir out;
        QVERIFY(root.isValid() && out.isValid());
        const auto run = [&] {
            return test::runRosarch({QStringLiteral("recover"), workspace(),
                                     QStringLiteral("--out"), out.path(),
                                     QStringLiteral("--in-process"),
                                     QStringLiteral("--no-decisions"), QStringLiteral("--quiet")},
                                    {{QStringLiteral("ROSARCH_NO_CACHE"), QStringLiteral("0")},
                                     {QStringLiteral("ROSARCH_CACHE_DIR"), root.path()}})
                       .exitCode == 0;
        };
        QVERIFY(run());
        const QStringList packs = packsIn(root.path());
        QCOMPARE(packs.size(), 1); // written before the process ended
        QVERIFY(run());
        QCOMPARE(packsIn(root.path()), packs); // warm: nothing new to write
    }
};

QTEST_GUILESS_MAIN(TestDeferredCacheWrite)
#include "tst_deferredcachewrite.moc"
