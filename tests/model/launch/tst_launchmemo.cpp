// Stage 2's memo in the analysis cache: keyed by what the launch executor uses of stage 1's
// result, so that an edit moving the lines of a node file without changing its classes does
// not run stage 2 again, while a changed executable name does; either way the result is the
// one an uncached run gives.
#include "cache/analysiscache.h"
#include "launch/launchanalyzer.h"
#include "nodes/nodeanalyzer.h"
#include "support/cachetestcase.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

struct Stages
{
    AtomicNodeList nodes;
    LaunchDependencies launch;
    AnalysisCache::Statistics launchStatistics; ///< of stage 2 alone
};

Stages run(const QString &root, AnalysisCache *cache, const AtomicNodeList *nodes = nullptr)
{
    StageControl control;
    control.cache = cache;
    const Workspace ws = WorkspaceScanner::scan(root, control);
    Stages out;
    out.nodes = nodes ? *nodes : NodeAnalyzer::run(ws, control);
    const AnalysisCache::Statistics before = cache->statistics();
    out.launch = LaunchAnalyzer::run(ws, out.nodes, {}, control);
    const AnalysisCache::Statistics after = cache->statistics();
    out.launchStatistics = {after.hits - before.hits, after.misses - before.misses,
                            after.rejected - before.rejected, after.stores - before.stores};
    return out;
}

LaunchDependencies uncachedLaunch(const QString &root, const AtomicNodeList &nodes)
{
    AnalysisCache off{QString()};
    return run(root, &off, &nodes).launch;
}

} // namespace

class TestLaunchMemo : public QObject
{
    Q_OBJECT

    QTemporaryDir m_temp;
    QString m_ws;
    QString m_cache;

private Q_SLOTS:
    void init()
    {
        QVERIFY(m_temp.isValid());
        test::freshCacheCase(m_temp, &m_ws, &m_cache);
    }

    void aCommentMovingNodeLinesKeepsTheMemo()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Stages cold = run(m_ws, &first);
        QCOMPARE(cold.launchStatistics.stores, 3); // 2 launch files and the memo

        // The detector's ports move a line down; nothing stage 2 uses of them changes.
        const QString detector = m_ws + QStringLiteral("/src/vision/src/detector.cpp");
        test::writeFile(detector, "// a comment\n" + test::readFile(detector));
        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Stages edited = run(m_ws, &second);
        QVERIFY(edited.nodes != cold.nodes); // the evidence lines moved
        QCOMPARE(edited.launchStatistics.hits, 1);
        QCOMPARE(edited.launchStatistics.misses, 0);
        QCOMPARE(edited.launchStatistics.stores, 0);
        QVERIFY(edited.launch == cold.launch);
        QVERIFY(edited.launch == uncachedLaunch(m_ws, edited.nodes));
    }

    void aChangedExecutableNameRunsStage2Again()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Stages cold = run(m_ws, &first);
        AtomicNodeList renamed = cold.nodes;
        bool found = false;
        for (AtomicNode &n : renamed.nodes)
            if (n.executables.contains(QStringLiteral("camera"))) {
                n.executables = {QStringLiteral("camera_driver")};
                found = true;
            }
        QVERIFY2(found, "the fixture's Camera class is built as the camera executable");

        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Stages again = run(m_ws, &second, &renamed);
        QCOMPARE(again.launchStatistics.misses, 1); // the memo; the launch files are hits
        QCOMPARE(again.launchStatistics.stores, 1);
        QVERIFY(again.launch != cold.launch); // the camera instance is no longer typed
        QVERIFY(again.launch == uncachedLaunch(m_ws, renamed));
    }

    void aChangedParameterFileRunsStage2Again()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Stages cold = run(m_ws, &first);
        // A new launch file: a file of the scan that stage 2 reads.
        test::writeFile(m_ws + QStringLiteral("/src/vision/launch/extra.launch.xml"),
                        "<launch>\n  <node pkg=\"vision\" exec=\"camera\" name=\"cam2\"/>\n"
                        "</launch>\n");
        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Stages again = run(m_ws, &second, &cold.nodes);
        QVERIFY(again.launchStatistics.misses >= 1);
        QVERIFY(again.launch != cold.launch);
        QVERIFY(again.launch == uncachedLaunch(m_ws, cold.nodes));
    }
};

QTEST_GUILESS_MAIN(TestLaunchMemo)
#include "tst_launchmemo.moc"
