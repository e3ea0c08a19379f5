// The serial tail of a run, made concurrent: stage 3 composes the launch files' own
// classifiers on a pool thread while it composes and checks the systems, and the worker sends
// each stage's part of its reply as soon as the stage is done. Whatever the interleaving, the
// result is the one of a run on one thread; progress counts up once per instance; a cancel
// ends stage 3 without a hang; the parts read one by one give the whole reply.
#include "cache/analysiscache.h"
#include "compose/composearchitecture.h"
#include "pipeline/recovery.h"
#include "pipeline/recoverystream.h"
#include "support/testsupport.h"

#include <QThreadPool>
#include <QtTest>

#include <atomic>
#include <mutex>

using namespace rosarch;
using test::PoolSize;

namespace {

const char *const kWorkspaces[] = {"compose_system/ws", "launch_formats/ws",
                                   "launch_constructs/ws"};

QString workspace(const char *name)
{
    return test::dataDir(QString::fromLatin1(name));
}

QByteArray parts(quint8 which, const Recovery &r, const Recovery &base)
{
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(stagestream::kStreamVersion);
    stagestream::writeParts(out, which, r, base);
    return bytes;
}

bool readParts(const QByteArray &bytes, Recovery *into, const Recovery &base, quint8 *read)
{
    QDataStream in(bytes);
    in.setVersion(stagestream::kStreamVersion);
    return stagestream::readParts(in, into, base, read);
}

} // namespace

class TestSerialTail : public QObject
{
    Q_OBJECT

    AnalysisCache m_off{QString()};

    StageControl uncached() const
    {
        StageControl c;
        c.cache = const_cast<AnalysisCache *>(&m_off);
        return c;
    }

private Q_SLOTS:
    void stageThreeIsTheSameOnAnyNumberOfThreads_data()
    {
        QTest::addColumn<QString>("root");
        for (const char *name : kWorkspaces)
            QTest::newRow(name) << workspace(name);
    }
    void stageThreeIsTheSameOnAnyNumberOfThreads()
    {
        QFETCH(QString, root);
        const Recovery r = recoverWorkspace(root, {}, uncached());
        QVERIFY(!r.launch.classifierInstances.isEmpty()); // the part composed on a pool thread
        QVERIFY(!r.architecture.classifiers.isEmpty());
        Architecture alone;
        {
            const PoolSize one(1); // the calling thread takes the classifiers' task back
            alone = composeArchitecture(r.nodes, r.launch, uncached());
        }
        QVERIFY(alone == r.architecture);
        for (const int threads : {2, 4, 8})
            for (int run = 0; run < 5; ++run) {
                const PoolSize size(threads);
                QVERIFY(composeArchitecture(r.nodes, r.launch, uncached()) == alone);
            }
    }

    void progressCountsEachInstanceOnce()
    {
        const Recovery r = recoverWorkspace(workspace("compose_system/ws"), {}, uncached());
        const int all = int(r.launch.instances.size() + r.launch.classifierInstances.size());
        std::mutex mutex;
        QList<int> done;
        StageControl control = uncached();
        control.progressed = [&](int d, int total, const QString &) {
            const std::lock_guard lock(mutex);
            QCOMPARE(total, all);
            done.append(d);
        };
        const Architecture arch = composeArchitecture(r.nodes, r.launch, control);
        QVERIFY(!arch.canceled);
        std::sort(done.begin(), done.end());
        QList<int> expected;
        for (int i = 1; i <= all; ++i)
            expected.append(i);
        QCOMPARE(done, expected);
    }

    void aCancelInStageThreeEndsIt()
    {
        const Recovery r = recoverWorkspace(workspace("launch_constructs/ws"), {}, uncached());
        for (int after = 0; after < 4; ++after) {
            std::atomic<int> reports{0};
            StageControl control = uncached();
            control.progressed = [&](int, int, const QString &) { ++reports; };
            control.canceled = [&] { return reports.load() > after; };
            const Architecture arch = composeArchitecture(r.nodes, r.launch, control);
            QVERIFY(arch.canceled);
            QVERIFY(arch.classifiers.isEmpty()); // a canceled stage keeps no half of them
        }
    }

    void partsSentAheadGiveTheWholeReply_data() { stageThreeIsTheSameOnAnyNumberOfThreads_data(); }
    void partsSentAheadGiveTheWholeReply()
    {
        QFETCH(QString, root);
        const Recovery r = recoverWorkspace(root, {}, uncached());
        Recovery older = r; // a previous reply that differs in a part of each stage
        older.nodes.nodes.removeLast();
        older.launch.nodes.first().nodeName += QStringLiteral("_before");
        older.architecture.composites.removeFirst();
        for (const Recovery &base : {Recovery{}, older, r}) {
            Recovery back;
            quint8 read = 0;
            // In the order the worker's threads may write them, the Result's part last or not.
            QVERIFY(readParts(parts(stagestream::LaunchPart, r, base), &back, base, &read));
            QCOMPARE(read, quint8(stagestream::LaunchPart));
            QVERIFY(readParts(parts(stagestream::NodesPart, r, base), &back, base, &read));
            QVERIFY(read != stagestream::AllParts);
            QVERIFY(readParts(parts(stagestream::ArchitecturePart, r, base), &back, base, &read));
            QCOMPARE(read, quint8(stagestream::AllParts));
            QVERIFY(back == r);
        }
        // A reply without all its parts is no result.
        Recovery partial;
        QDataStream in(parts(stagestream::NodesPart | stagestream::LaunchPart, r, {}));
        in.setVersion(stagestream::kStreamVersion);
        QVERIFY(!stagestream::readResult(in, &partial, {}));
        // Nor is a part that names parts there are not.
        quint8 read = 0;
        QByteArray bad = parts(stagestream::NodesPart, r, {});
        bad[0] = char(0x48);
        QVERIFY(!readParts(bad, &partial, {}, &read));
        QCOMPARE(read, quint8(0));
    }

    void aRequestSaysWhetherItIsTheLast()
    {
        for (const bool last : {false, true}) {
            StageRequest request;
            request.root = QStringLiteral("/ws");
            request.last = last;
            StageRequest back;
            QVERIFY(stagestream::decodeRequest(stagestream::encodeRequest(request), &back));
            QCOMPARE(back.last, last);
            QCOMPARE(back.root, request.root);
        }
    }
};

QTEST_GUILESS_MAIN(TestSerialTail)
#include "tst_serialtail.moc"
