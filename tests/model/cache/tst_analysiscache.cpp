// The analysis cache: a second run reads every file from it and gives the same recovery; an
// edit re-analyses exactly the edited file (and a header's macros reach the files including
// it); damaged entries and an unusable folder cost the cache, never the result; the size bound
// evicts the oldest entries. Every cache lives in a temporary folder.
#include "analysiscache.h"
#include "recovery.h"
#include "testsupport.h"

#include <QDirIterator>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

/// Stages 1-3 on `root` with `cache`; the cache's statistics of that run only.
Recovery recoverWith(const QString &root, AnalysisCache *cache)
{
    StageControl control;
    control.cache = cache;
    return recoverWorkspace(root, {}, control);
}

Recovery recoverUncached(const QString &root)
{
    AnalysisCache off{QString()};
    return recoverWith(root, &off);
}

QStringList entries(const QString &cacheRoot)
{
    QStringList out;
    QDirIterator it(cacheRoot, QDir::Files, QDirIterator::Subdirectories);
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

int countCode(const Recovery &r, const QString &code)
{
    int n = 0;
    for (const QList<Diagnostic> *list :
         {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics})
        for (const Diagnostic &d : *list)
            n += d.code == code ? 1 : 0;
    return n;
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
        m_ws = m_temp.filePath(QStringLiteral("ws-%1").arg(QTest::currentTestFunction()));
        m_cache = m_temp.filePath(QStringLiteral("cache-%1").arg(QTest::currentTestFunction()));
        test::copyTree(test::dataDir(QStringLiteral("compose_system/ws")), m_ws);
    }

    void secondRunReadsEveryFileFromCache()
    {
        AnalysisCache first(m_cache);
        QVERIFY(first.isEnabled());
        const Recovery cold = recoverWith(m_ws, &first);
        // 3 C++ files, 4 Python files (the launch file among them), 2 launch files.
        QCOMPARE(first.statistics().stores, 9);
        QCOMPARE(first.statistics().hits, 0);
        QCOMPARE(entries(m_cache).size(), 9);
        QVERIFY(!cold.nodes.nodes.isEmpty());
        QVERIFY(!cold.architecture.composites.isEmpty());

        AnalysisCache second(m_cache);
        const Recovery warm = recoverWith(m_ws, &second);
        QCOMPARE(second.statistics().hits, 9);
        QCOMPARE(second.statistics().misses, 0);
        QCOMPARE(second.statistics().stores, 0);
        QVERIFY(warm == cold);
        QVERIFY(warm == recoverUncached(m_ws));
    }

    void editingOneFileReanalysesExactlyThatFile()
    {
        AnalysisCache first(m_cache);
        recoverWith(m_ws, &first);
        const QString camera = m_ws + QStringLiteral("/src/vision/src/camera.cpp");
        QByteArray source = test::readFile(camera);
        const qsizetype at = source.indexOf("\"image_raw\"");
        QVERIFY2(at >= 0, "the fixture's camera publishes image_raw");
        source.replace(at, 11, "\"image_edited\"");
        test::writeFile(camera, source);

        AnalysisCache second(m_cache);
        const Recovery edited = recoverWith(m_ws, &second);
        QCOMPARE(second.statistics().misses, 1);
        QCOMPARE(second.statistics().stores, 1);
        QCOMPARE(second.statistics().hits, 8);
        QVERIFY(edited == recoverUncached(m_ws));
        bool found = false;
        for (const AtomicNode &n : edited.nodes.nodes)
            for (const Port &p : n.ports)
                found = found || p.name == QLatin1String("image_edited");
        QVERIFY(found);
    }

    void aHeaderMacroChangeReanalysesTheFilesThatUseIt()
    {
        const QString ws = m_temp.filePath(QStringLiteral("rover"));
        test::copyTree(test::dataDir(QStringLiteral("cpp_preprocessor/ws")), ws);
        AnalysisCache first(m_cache);
        const Recovery before = recoverWith(ws, &first);
        QVERIFY(portNames(before, QStringLiteral("RoverDriver")).contains(QStringLiteral("odom")));

        // Only the header changes; the source file that uses its macro is the same text.
        const QString header = ws + QStringLiteral("/src/rover_base/include/rover_base/topics.hpp");
        QByteArray text = test::readFile(header);
        text.replace("#define ROVER_ODOM_TOPIC \"odom\"", "#define ROVER_ODOM_TOPIC \"odometry\"");
        test::writeFile(header, text);
        AnalysisCache second(m_cache);
        const Recovery after = recoverWith(ws, &second);
        QVERIFY(
            portNames(after, QStringLiteral("RoverDriver")).contains(QStringLiteral("odometry")));
        QVERIFY(after == recoverUncached(ws));
        QVERIFY(second.statistics().misses >= 2); // the header and the driver that includes it
    }

    void damagedEntriesAreAnalysedAgain()
    {
        AnalysisCache first(m_cache);
        const Recovery cold = recoverWith(m_ws, &first);
        const QStringList files = entries(m_cache);
        QCOMPARE(files.size(), 9);
        // Truncated, a flipped byte, another entry's bytes (foreign), garbage, empty.
        const QByteArray other = test::readFile(files.at(1));
        QFile truncated(files.at(0));
        QVERIFY(truncated.resize(truncated.size() / 2));
        QByteArray flipped = test::readFile(files.at(2));
        flipped[flipped.size() / 2] = char(flipped.at(flipped.size() / 2) ^ 0x5a);
        test::writeFile(files.at(2), flipped);
        test::writeFile(files.at(3), other);
        test::writeFile(files.at(4), QByteArray(4096, '\xff'));
        test::writeFile(files.at(5), QByteArray());

        AnalysisCache second(m_cache);
        const Recovery again = recoverWith(m_ws, &second);
        QCOMPARE(second.statistics().rejected, 5);
        QCOMPARE(second.statistics().hits, 4);
        QCOMPARE(second.statistics().stores, 5); // written anew
        QVERIFY(again == cold);

        AnalysisCache third(m_cache);
        QVERIFY(recoverWith(m_ws, &third) == cold);
        QCOMPARE(third.statistics().hits, 9);
    }

    void anUnusableFolderMeansNoCacheAndOneDiagnostic()
    {
        // A file where the cache folder would be: it cannot be created.
        test::writeFile(m_cache, "not a folder");
        AnalysisCache blocked(m_cache + QStringLiteral("/below"));
        QVERIFY(!blocked.isEnabled());
        const Recovery r = recoverWith(m_ws, &blocked);
        QCOMPARE(countCode(r, QStringLiteral("cache-unavailable")), 1);
        QCOMPARE(r.nodes.nodes, recoverUncached(m_ws).nodes.nodes);
        QCOMPARE(r.architecture, recoverUncached(m_ws).architecture);
    }

    void aFailedWriteTurnsTheCacheOffForTheRun()
    {
        // The C++ entries cannot be written (as on a full disk); the run goes on without them.
        AnalysisCache cache(m_cache);
        QVERIFY(cache.isEnabled());
        test::writeFile(cache.directory() + QStringLiteral("/cpp"), "in the way");
        const Recovery r = recoverWith(m_ws, &cache);
        QVERIFY(!cache.isEnabled());
        QCOMPARE(countCode(r, QStringLiteral("cache-unavailable")), 1);
        Recovery uncached = recoverUncached(m_ws);
        QCOMPARE(r.nodes.nodes, uncached.nodes.nodes);
        QCOMPARE(r.launch.nodes, uncached.launch.nodes);
    }

    void theSizeBoundEvictsTheOldestEntries()
    {
        AnalysisCache cache(m_cache, 10 * 1024);
        const QByteArray payload(3000, 'x');
        for (int i = 0; i < 6; ++i)
            cache.store(QStringLiteral("cpp"), AnalysisCache::key({QByteArray::number(i)}),
                        payload);
        QStringList files = entries(m_cache);
        QCOMPARE(files.size(), 6);
        // Entry i was written i hours ago: the oldest are the highest numbers.
        for (int i = 0; i < 6; ++i) {
            const QString path =
                cache.directory() + QStringLiteral("/cpp/") +
                QString::fromLatin1(AnalysisCache::key({QByteArray::number(i)}).toHex().left(2)) +
                QLatin1Char('/') +
                QString::fromLatin1(AnalysisCache::key({QByteArray::number(i)}).toHex());
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadWrite));
            QVERIFY(f.setFileTime(QDateTime::currentDateTime().addSecs(-3600 * i),
                                  QFileDevice::FileModificationTime));
        }
        cache.trim();
        files = entries(m_cache);
        QCOMPARE(files.size(), 3); // 3 entries of ~3 KB fit in 90% of 10 KB, 4 do not
        for (int i = 0; i < 6; ++i)
            QCOMPARE(bool(cache.load(QStringLiteral("cpp"),
                                     AnalysisCache::key({QByteArray::number(i)}))),
                     i < 3);
    }
};

QTEST_GUILESS_MAIN(TestAnalysisCache)
#include "tst_analysiscache.moc"
