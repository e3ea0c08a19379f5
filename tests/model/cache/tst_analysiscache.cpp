// The analysis cache: a second run reads its stages from the cache and gives the same
// recovery; an edit re-analyses exactly the edited file (and a header's macros reach the files
// including it); a deferred flush writes when told to; damaged and vanished packs cost the
// cache, never the result; two caches share a folder; an unusable folder means one diagnostic;
// the size bound evicts the oldest packs.
// Every cache lives in a temporary folder.
#include "cache/analysiscache.h"
#include "pipeline/recovery.h"
#include "support/cacherecovery.h"
#include "support/cachetestcase.h"
#include "support/testsupport.h"

#include <QDirIterator>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

QStringList packs(const QString &cacheRoot)
{
    QStringList out;
    QDirIterator it(cacheRoot, {QStringLiteral("*.pack")}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext())
        out << it.next();
    out.sort();
    return out;
}

QStringList portNames(const Recovery &r, const QString &className)
{
    QStringList names;
    for (const AtomicNode &n : r.nodes.nodes)
        if (n.className == className)
            for (const Port &p : n.ports)
                names << p.name;
    return names;
}

QList<Diagnostic> withCode(const Recovery &r, const QString &code)
{
    QList<Diagnostic> out;
    for (const QList<Diagnostic> *list :
         {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics})
        for (const Diagnostic &d : *list)
            if (d.code == code)
                out.append(d);
    return out;
}

QByteArray keyOf(int i)
{
    return AnalysisCache::key({QByteArray::number(i)});
}

} // namespace

class TestAnalysisCache : public QObject
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

    void secondRunReadsBothStagesFromTheCache()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        QVERIFY(first.isEnabled());
        const Recovery cold = test::recoverWith(m_ws, &first);
        // 3 C++ files, 4 Python files (the launch file among them), 2 launch files; the
        // memos of stages 1, 2 and 3, the macro index and the 3 C++ manifests.
        QCOMPARE(first.statistics().stores, 16);
        QCOMPARE(first.statistics().hits, 0);
        QCOMPARE(packs(m_cache).size(), 3); // one per stage's flush
        QVERIFY(!cold.nodes.nodes.isEmpty());
        QVERIFY(!cold.architecture.composites.isEmpty());

        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Recovery warm = test::recoverWith(m_ws, &second);
        QCOMPARE(second.statistics().hits, 3); // the three memos, nothing per file
        QCOMPARE(second.statistics().misses, 0);
        QCOMPARE(second.statistics().stores, 0);
        QCOMPARE(second.digests().hashed(), 0); // every file known by its stat
        QVERIFY(warm == cold);
        QVERIFY(warm == test::recoverUncached(m_ws));
    }

    void editingOneFileReanalysesExactlyThatFile()
    {
        AnalysisCache first(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        test::recoverWith(m_ws, &first);
        const QString camera = m_ws + QStringLiteral("/src/vision/src/camera.cpp");
        QByteArray source = test::readFile(camera);
        const qsizetype at = source.indexOf("\"image_raw\"");
        QVERIFY2(at >= 0, "the fixture's camera publishes image_raw");
        source.replace(at, 11, "\"image_edited\"");
        test::writeFile(camera, source);

        AnalysisCache second(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const Recovery edited = test::recoverWith(m_ws, &second);
        // The memos of stages 1 and 3, camera.cpp, its manifest.
        QCOMPARE(second.statistics().misses, 4);
        QCOMPARE(second.statistics().stores, 4);
        QCOMPARE(second.digests().hashed(), 1);
        QVERIFY(edited == test::recoverUncached(m_ws));
        bool found = false;
        for (const AtomicNode &n : edited.nodes.nodes)
            for (const Port &p : n.ports)
                found = found || p.name == QLatin1String("image_edited");
        QVERIFY(found);
    }

    void aLongLivedProcessKeepsWhatItDecoded()
    {
        // The long-lived worker: one cache across runs. Once an entry is decoded, later runs
        // take the value kept in memory; an edit still re-analyses exactly the edited file, and
        // every result equals an uncached one.
        {
            AnalysisCache fill(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
            test::recoverWith(m_ws, &fill);
        }
        AnalysisCache cache(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        const QString camera = m_ws + QStringLiteral("/src/vision/src/camera.cpp");
        const QByteArray original = test::readFile(camera);
        test::writeFile(camera, "// moved one line down\n" + original);
        QVERIFY(test::recoverWith(m_ws, &cache) ==
                test::recoverUncached(m_ws)); // decodes from the packs
        const AnalysisCache::Statistics decoded = cache.statistics();

        test::writeFile(camera, "// moved two lines down\n\n" + original);
        const Recovery edited = test::recoverWith(m_ws, &cache);
        QVERIFY(edited == test::recoverUncached(m_ws));
        const AnalysisCache::Statistics kept = cache.statistics();
        // Misses: the memos of stages 1 and 3, camera.cpp's manifest and its facts; everything
        // else came from memory (stage 2's memo too, with camera's parameter defaults moved),
        // nothing from a pack.
        QCOMPARE(kept.misses - decoded.misses, 4);
        QCOMPARE(decoded.kept, 0);
        QVERIFY(kept.kept > 0);
        QCOMPARE(kept.kept - decoded.kept, kept.hits - decoded.hits);
        // The kept facts are the ones a fresh process decodes.
        AnalysisCache fresh(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        QVERIFY(test::recoverWith(m_ws, &fresh) == edited);

        // Back to the original text: every result matches again, from memory or packs.
        test::writeFile(camera, original);
        QVERIFY(test::recoverWith(m_ws, &cache) == test::recoverUncached(m_ws));
        // Nothing is kept in a cache that is off.
        AnalysisCache off{QString()};
        off.keepRecent(QStringLiteral("cpp"), keyOf(1), std::make_shared<const int>(1));
        QVERIFY(!off.recent(QStringLiteral("cpp"), keyOf(1)));
        // A run drops what the run before it did not use.
        cache.keepRecent(QStringLiteral("test"), keyOf(2), std::make_shared<const int>(2));
        QVERIFY(cache.recent(QStringLiteral("test"), keyOf(2)));
        cache.startRun({QStringLiteral("test")});
        QVERIFY(cache.recent(QStringLiteral("test"), keyOf(2))); // used in the run before
        cache.startRun({QStringLiteral("test")});
        cache.startRun({QStringLiteral("test")});
        QVERIFY(!cache.recent(QStringLiteral("test"), keyOf(2)));
    }

    void aHeaderMacroChangeReanalysesTheFilesThatUseIt()
    {
        const QString ws = m_temp.filePath(QStringLiteral("rover"));
        test::copyTree(test::dataDir(QStringLiteral("cpp_preprocessor/ws")), ws);
        AnalysisCache first(m_cache);
        const Recovery before = test::recoverWith(ws, &first);
        QVERIFY(portNames(before, QStringLiteral("RoverDriver")).contains(QStringLiteral("odom")));

        // Only the header changes; the source file that uses its macro is the same text.
        const QString header = ws + QStringLiteral("/src/rover_base/include/rover_base/topics.hpp");
        QByteArray text = test::readFile(header);
        text.replace("#define ROVER_ODOM_TOPIC \"odom\"", "#define ROVER_ODOM_TOPIC \"odometry\"");
        test::writeFile(header, text);
        AnalysisCache second(m_cache);
        const Recovery after = test::recoverWith(ws, &second);
        QVERIFY(
            portNames(after, QStringLiteral("RoverDriver")).contains(QStringLiteral("odometry")));
        QVERIFY(after == test::recoverUncached(ws));
        QVERIFY(second.statistics().misses >= 3); // the memo, the header, the driver
    }

    void damagedPacksAreAnalysedAgain()
    {
        AnalysisCache first(m_cache);
        const Recovery cold = test::recoverWith(m_ws, &first);
        const QStringList files = packs(m_cache);
        QCOMPARE(files.size(), 3); // stage 1's, stage 2's and stage 3's
        // A flipped byte inside the first pack's entries; the second pack truncated; a
        // foreign file named like a pack.
        // (the last entry before the index, the stage 1 memo)
        QByteArray flipped = test::readFile(files.at(0));
        const qint64 indexAt = qFromBigEndian<qint64>(flipped.constData() + flipped.size() - 32);
        flipped[indexAt - 10] = char(flipped.at(indexAt - 10) ^ 0x5a);
        test::writeFile(files.at(0), flipped);
        QFile truncated(files.at(1));
        QVERIFY(truncated.resize(truncated.size() / 2));
        test::writeFile(QFileInfo(files.at(0)).path() + QStringLiteral("/0-garbage.pack"),
                        QByteArray(4096, '\xff'));

        AnalysisCache second(m_cache);
        const Recovery again = test::recoverWith(m_ws, &second);
        QCOMPARE(second.statistics().rejected, 3);
        QVERIFY(again == cold);

        AnalysisCache third(m_cache);
        QVERIFY(test::recoverWith(m_ws, &third) == cold);
        QCOMPARE(third.statistics().misses, 0);
    }

    void aVanishedPackIsAMiss()
    {
        {
            AnalysisCache writer(m_cache);
            writer.store(QStringLiteral("cpp"), keyOf(1), "one");
            writer.store(QStringLiteral("cpp"), keyOf(2), "two");
        } // flushed when destroyed
        AnalysisCache opened(m_cache);
        QCOMPARE(opened.load(QStringLiteral("cpp"), keyOf(1)), std::optional<QByteArray>("one"));
        AnalysisCache notYetOpened(m_cache);
        for (const QString &pack : packs(m_cache)) // as another process's trim would
            QVERIFY(QFile::remove(pack));
        // A pack already open stays readable; one gone before it was opened is a miss.
        QCOMPARE(opened.load(QStringLiteral("cpp"), keyOf(2)), std::optional<QByteArray>("two"));
        QVERIFY(!notYetOpened.load(QStringLiteral("cpp"), keyOf(2)));
        QCOMPARE(notYetOpened.statistics().misses, 1);
        QVERIFY(test::recoverWith(m_ws, &notYetOpened) == test::recoverUncached(m_ws));
    }

    void twoCachesShareAFolder()
    {
        AnalysisCache a(m_cache);
        AnalysisCache b(m_cache);
        const Recovery ra = test::recoverWith(m_ws, &a);
        const Recovery rb = test::recoverWith(m_ws, &b);
        a.store(QStringLiteral("cpp"), keyOf(1), "from a");
        b.store(QStringLiteral("cpp"), keyOf(2), "from b");
        b.flush();
        a.flush();
        QVERIFY(ra == rb);
        AnalysisCache c(m_cache);
        QCOMPARE(c.load(QStringLiteral("cpp"), keyOf(1)), std::optional<QByteArray>("from a"));
        QCOMPARE(c.load(QStringLiteral("cpp"), keyOf(2)), std::optional<QByteArray>("from b"));
        QVERIFY(test::recoverWith(m_ws, &c) == ra);
        QCOMPARE(c.statistics().rejected, 0);
        // No temporary file is left behind.
        QDirIterator it(m_cache, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
        while (it.hasNext())
            QVERIFY2(!it.next().contains(QLatin1String(".tmp-")), qPrintable(it.filePath()));
    }

    void aDeferredFlushWritesWhenTheWorkerHasReplied()
    {
        AnalysisCache cache(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        cache.setDeferFlush(true);
        cache.store(QStringLiteral("test"), keyOf(1), "one");
        cache.flush(); // what a stage calls: nothing is written yet
        QVERIFY(packs(m_cache).isEmpty());
        QCOMPARE(cache.load(QStringLiteral("test"), keyOf(1)), std::optional<QByteArray>("one"));
        cache.flushDeferred(); // what the worker calls once it has replied
        cache.waitForWrites();
        QCOMPARE(packs(m_cache).size(), 1);
        AnalysisCache other(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        QCOMPARE(other.load(QStringLiteral("test"), keyOf(1)), std::optional<QByteArray>("one"));
    }

    void theNextRunGoesOnWhilePacksAreWritten()
    {
        // Back-to-back runs of a long-lived worker: each flushDeferred() writes in the
        // background while the next run loads and stores (or, while a write still runs, leaves
        // its entries for the next one); every entry is found throughout, the last store of a
        // key wins, and the writes end as complete packs.
        constexpr int kRuns = 3 * AnalysisCache::kMaxPacks; // merges happen in the background too
        constexpr int kPerRun = 40;
        {
            AnalysisCache cache(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
            cache.setDeferFlush(true);
            for (int run = 0; run < kRuns; ++run) {
                for (int i = 0; i < kPerRun; ++i) {
                    const int n = run * kPerRun + i;
                    cache.store(QStringLiteral("cpp"), keyOf(n), QByteArray::number(n));
                }
                cache.store(QStringLiteral("stage1"), keyOf(0), QByteArray::number(run));
                cache.flush(); // deferred: nothing waits
                for (int n = 0; n < (run + 1) * kPerRun; n += 7)
                    QCOMPARE(cache.load(QStringLiteral("cpp"), keyOf(n)),
                             std::optional<QByteArray>(QByteArray::number(n)));
                QCOMPARE(cache.load(QStringLiteral("stage1"), keyOf(0)),
                         std::optional<QByteArray>(QByteArray::number(run)));
                cache.flushDeferred(); // the reply is out: the pack is written meanwhile
            }
            QVERIFY(!cache.takeProblem());
        } // the destructor waits for the last write
        QVERIFY(packs(m_cache).size() <= AnalysisCache::kMaxPacks);
        AnalysisCache reader(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        for (int n = 0; n < kRuns * kPerRun; ++n)
            QCOMPARE(reader.load(QStringLiteral("cpp"), keyOf(n)),
                     std::optional<QByteArray>(QByteArray::number(n)));
        QCOMPARE(reader.load(QStringLiteral("stage1"), keyOf(0)),
                 std::optional<QByteArray>(QByteArray::number(kRuns - 1)));
        QCOMPARE(reader.statistics().rejected, 0);
    }

    void aFailedBackgroundWriteIsSaidByTheNextRun()
    {
        AnalysisCache cache(m_cache, AnalysisCache::kDefaultMaxBytes, 0);
        cache.setDeferFlush(true);
        cache.store(QStringLiteral("cpp"), keyOf(1), "one");
        QVERIFY(QDir(cache.directory()).removeRecursively());
        QVERIFY(QFile(cache.directory()).open(QIODevice::WriteOnly)); // a file where the folder was
        cache.flushDeferred();
        cache.waitForWrites();
        const std::optional<Diagnostic> problem = cache.takeProblem();
        QVERIFY(problem);
        QCOMPARE(problem->code, QStringLiteral("cache-unavailable"));
        QVERIFY(!cache.isEnabled());
        QFile::remove(cache.directory());
    }

    void manyPacksAreMerged()
    {
        AnalysisCache cache(m_cache);
        for (int i = 0; i < 3 * AnalysisCache::kMaxPacks; ++i) {
            cache.store(QStringLiteral("cpp"), keyOf(i), QByteArray::number(i));
            cache.flush();
        }
        QVERIFY(packs(m_cache).size() <= AnalysisCache::kMaxPacks);
        AnalysisCache reader(m_cache);
        for (int i = 0; i < 3 * AnalysisCache::kMaxPacks; ++i)
            QCOMPARE(reader.load(QStringLiteral("cpp"), keyOf(i)),
                     std::optional<QByteArray>(QByteArray::number(i)));
    }

    void anUnusableFolderMeansNoCacheAndOneDiagnostic()
    {
        // A file where the cache folder would be: it cannot be created.
        test::writeFile(m_cache, "not a folder");
        AnalysisCache blocked(m_cache + QStringLiteral("/below"));
        QVERIFY(!blocked.isEnabled());
        const Recovery r = test::recoverWith(m_ws, &blocked);
        const QList<Diagnostic> problems = withCode(r, QStringLiteral("cache-unavailable"));
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.at(0).message.contains(m_cache + QStringLiteral("/below")));
        QCOMPARE(problems.at(0).related.size(), 1);
        QVERIFY(problems.at(0).related.at(0).evidence.file.startsWith(m_cache));
        QCOMPARE(r.nodes.nodes, test::recoverUncached(m_ws).nodes.nodes);
        QCOMPARE(r.architecture, test::recoverUncached(m_ws).architecture);
    }

    void aFailedWriteTurnsTheCacheOffForTheRun()
    {
        // The folder is replaced by a file after the cache opened it (as a full disk would
        // refuse the pack); the run goes on without the cache.
        AnalysisCache cache(m_cache);
        QVERIFY(cache.isEnabled());
        QVERIFY(QDir(cache.directory()).removeRecursively());
        test::writeFile(cache.directory(), "in the way");
        const Recovery r = test::recoverWith(m_ws, &cache);
        QVERIFY(!cache.isEnabled());
        const QList<Diagnostic> problems = withCode(r, QStringLiteral("cache-unavailable"));
        QCOMPARE(problems.size(), 1);
        QVERIFY(problems.at(0).message.contains(cache.directory()));
        Recovery uncached = test::recoverUncached(m_ws);
        QCOMPARE(r.nodes.nodes, uncached.nodes.nodes);
        QCOMPARE(r.launch.nodes, uncached.launch.nodes);
    }

    void theSizeBoundEvictsTheOldestPacks()
    {
        AnalysisCache cache(m_cache, 10 * 1024);
        const QByteArray payload(2900, 'x');
        for (int i = 0; i < 6; ++i) { // one pack each, written in order
            cache.store(QStringLiteral("cpp"), keyOf(i), payload);
            cache.flush();
        }
        QCOMPARE(packs(m_cache).size(), 3); // 3 packs of ~3 KB fit in 90% of 10 KB, 4 do not
        for (int i = 0; i < 6; ++i)
            QCOMPARE(bool(cache.load(QStringLiteral("cpp"), keyOf(i))), i >= 3);
    }

    void theBoundComesFromTheEnvironment()
    {
        qputenv("ROSARCH_CACHE_MAX_MB", "12");
        QCOMPARE(AnalysisCache::defaultMaxBytes(), 12LL * 1024 * 1024);
        qputenv("ROSARCH_CACHE_MAX_MB", "none");
        QCOMPARE(AnalysisCache::defaultMaxBytes(), AnalysisCache::kDefaultMaxBytes);
        qunsetenv("ROSARCH_CACHE_MAX_MB");
    }
};

QTEST_GUILESS_MAIN(TestAnalysisCache)
#include "tst_analysiscache.moc"
