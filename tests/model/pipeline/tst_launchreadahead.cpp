// Cold recovery's concurrency: stage 2's launch files read while stage 1 runs (LaunchReadAhead)
// give what reading them in stage 2 gives, whatever the threads' interleaving; a cancel during
// the overlap ends the run without a hang; the worker's reply sends each string once; a worker
// let go after its reply (WorkerProcess::release) is still reaped.
#include "cache/analysiscache.h"
#include "compose/composearchitecture.h"
#include "launch/launchfilecodec.h"
#include "launch/launchfileindex.h"
#include "launch/launchreadahead.h"
#include "nodes/nodeanalyzer.h"
#include "pipeline/recovery.h"
#include "pipeline/recoverystream.h"
#include "pipeline/workerprocess.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QThreadPool>
#include <QtTest>

#include <atomic>
#include <cerrno>
#include <csignal>

using namespace rosarch;

namespace {

const char *const kWorkspaces[] = {"compose_system/ws", "launch_formats/ws",
                                   "launch_constructs/ws"};

QString workspace(const char *name)
{
    return test::dataDir(QString::fromLatin1(name));
}

/// What an index holds, as bytes to compare: each file's description, in order.
QByteArray contents(const LaunchFileIndex &index)
{
    QByteArray out;
    for (const QString &f : index.files())
        out += f.toUtf8() + '\0' + LaunchFileCodec::encode(*index.find(f)) + '\0';
    return out;
}

/// Stages 1 to 3 one after the other, nothing read ahead.
Recovery serially(const QString &root, const StageControl &control)
{
    const Workspace ws = WorkspaceScanner::scan(root, control);
    Recovery r;
    r.nodes = NodeAnalyzer::run(ws, control);
    r.launch = LaunchAnalyzer::run(ws, r.nodes, {}, control);
    r.architecture = composeArchitecture(r.nodes, r.launch, control);
    return r;
}

bool alive(pid_t pid)
{
    return pid > 0 && (::kill(pid, 0) == 0 || errno != ESRCH);
}

} // namespace

class TestLaunchReadAhead : public QObject
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
    void readingAheadGivesTheIndexStageTwoReads_data()
    {
        QTest::addColumn<QString>("root");
        for (const char *name : kWorkspaces)
            QTest::newRow(name) << workspace(name);
    }
    void readingAheadGivesTheIndexStageTwoReads()
    {
        QFETCH(QString, root);
        const StageControl control = uncached();
        const Workspace ws = WorkspaceScanner::scan(root, control);
        QList<Diagnostic> expectedDiagnostics;
        const LaunchFileIndex expected(ws, control, &expectedDiagnostics);
        QVERIFY(!expected.files().isEmpty());
        for (int run = 0; run < 5; ++run) { // the reading thread gets further or not
            LaunchReadAhead ahead(ws, control);
            std::optional<QList<LaunchFileRead>> reads = ahead.take();
            QVERIFY(reads);
            QList<Diagnostic> diagnostics;
            const LaunchFileIndex index(ws, std::move(*reads), control, &diagnostics);
            QCOMPARE(index.files(), expected.files());
            QCOMPARE(contents(index), contents(expected));
            QCOMPARE(diagnostics, expectedDiagnostics);
        }
    }

    void aRecoveryWithItEqualsOneWithout_data() { readingAheadGivesTheIndexStageTwoReads_data(); }
    void aRecoveryWithItEqualsOneWithout()
    {
        QFETCH(QString, root);
        const Recovery expected = serially(root, uncached());
        QVERIFY(!expected.launch.launchFiles.isEmpty());
        for (int run = 0; run < 3; ++run)
            QVERIFY(recoverWorkspace(root, {}, uncached()) == expected);
    }

    void oneAnalysisThreadReadsNothingAhead()
    {
        const StageControl control = uncached();
        const Workspace ws = WorkspaceScanner::scan(workspace(kWorkspaces[0]), control);
        const int threads = QThreadPool::globalInstance()->maxThreadCount();
        QThreadPool::globalInstance()->setMaxThreadCount(1);
        std::optional<QList<LaunchFileRead>> reads;
        {
            LaunchReadAhead ahead(ws, control);
            reads = ahead.take();
        }
        QThreadPool::globalInstance()->setMaxThreadCount(threads);
        QVERIFY(!reads); // stage 2 reads them itself, one file at a time
    }

    void aCacheWithEntriesReadsNothingAhead()
    {
        QTemporaryDir folder;
        AnalysisCache cache(folder.path(), AnalysisCache::kDefaultMaxBytes, 0);
        StageControl control;
        control.cache = &cache;
        const QString root = workspace("compose_system/ws");
        const Workspace ws = WorkspaceScanner::scan(root, control);
        QVERIFY(LaunchReadAhead(ws, control).reading()); // cold: nothing to answer stage 2
        const Recovery cold = recoverWorkspace(root, {}, control);
        QVERIFY(cold == serially(root, uncached()));
        QVERIFY(!LaunchReadAhead(ws, control).reading()); // its memo will, most likely
        QVERIFY(recoverWorkspace(root, {}, control) == cold);
    }

    void aCancelDuringTheOverlapEndsTheRun_data()
    {
        QTest::addColumn<int>("after");
        for (int after : {0, 1, 3, 6, 10, 15, 25, 40})
            QTest::addRow("after %d polls", after) << after;
    }
    void aCancelDuringTheOverlapEndsTheRun()
    {
        QFETCH(int, after);
        // The reading thread polls the same control: the cancel lands in the middle of it.
        auto polls = std::make_shared<std::atomic<int>>(0);
        StageControl control = uncached();
        control.canceled = [polls, after] { return polls->fetch_add(1) >= after; };
        const QString root = workspace("launch_constructs/ws");
        const Recovery r = recoverWorkspace(root, {}, control);
        const Recovery expected = serially(root, uncached());
        // Stage 1 is said to be canceled or is whole; a run the cancel never reached is whole.
        QVERIFY(r.nodes.canceled || r.nodes == expected.nodes);
        if (polls->load() <= after)
            QVERIFY(r == expected);
        else
            QVERIFY(r.architecture.composites.isEmpty() || r == expected);
    }

    void aCanceledReadingGivesNothing()
    {
        StageControl control = uncached();
        const Workspace ws = WorkspaceScanner::scan(workspace(kWorkspaces[0]), control);
        std::atomic<bool> cancel{false};
        control.canceled = [&cancel] { return cancel.load(); };
        LaunchReadAhead ahead(ws, control);
        cancel = true;
        QVERIFY(!ahead.take());
    }

    void goingUnusedStopsTheReading()
    {
        const StageControl control = uncached();
        const Workspace ws = WorkspaceScanner::scan(workspace("launch_constructs/ws"), control);
        for (int run = 0; run < 20; ++run)
            LaunchReadAhead ahead(ws, control);       // joined by its destructor, never taken
        QVERIFY(LaunchReadAhead(ws, control).take()); // and a later one still reads
    }

    void theReplySendsEachStringOnceAndKeepsNullStrings()
    {
        Recovery r = serially(workspace("compose_system/ws"), uncached());
        QVERIFY(!r.launch.nodes.isEmpty());
        r.nodes.diagnostics.append(Diagnostic{});
        r.nodes.diagnostics.last().message = QStringLiteral(""); // empty, not null
        QVERIFY(!r.nodes.diagnostics.last().message.isNull());
        QVERIFY(r.nodes.diagnostics.last().code.isNull());
        QByteArray bytes;
        {
            QDataStream out(&bytes, QIODevice::WriteOnly);
            out.setVersion(stagestream::kStreamVersion);
            stagestream::writeResult(out, r, {});
        }
        // A string in every diagnostic of a part is in the reply once, whatever their number.
        const QString marker = QStringLiteral("a message every diagnostic of this part repeats");
        Recovery repeated = r;
        for (int i = 0; i < 50; ++i) {
            repeated.nodes.diagnostics.append(Diagnostic{});
            repeated.nodes.diagnostics.last().message = marker;
        }
        QByteArray withRepeats;
        {
            QDataStream out(&withRepeats, QIODevice::WriteOnly);
            out.setVersion(stagestream::kStreamVersion);
            stagestream::writeResult(out, repeated, {});
        }
        QByteArray utf16; // as QDataStream writes a QString: UTF-16, big-endian
        for (const QChar c : marker)
            utf16 += char(c.unicode() >> 8) + QByteArray(1, char(c.unicode() & 0xff));
        QCOMPARE(withRepeats.count(utf16), 1);
        QVERIFY(withRepeats.size() - bytes.size() < 50 * utf16.size()); // not 50 copies
        Recovery back;
        QDataStream in(bytes);
        in.setVersion(stagestream::kStreamVersion);
        QVERIFY(stagestream::readResult(in, &back, {}));
        QVERIFY(back == r);
        QVERIFY(!back.nodes.diagnostics.last().message.isNull());
        QVERIFY(back.nodes.diagnostics.last().code.isNull());

        // A string number past the table is damage, not a crash.
        QByteArray damaged = bytes;
        for (qsizetype i = damaged.size() / 2; i < damaged.size(); i += 7)
            damaged[i] = char(0x7f);
        QDataStream bad(damaged);
        bad.setVersion(stagestream::kStreamVersion);
        Recovery ignored;
        const bool ok = stagestream::readResult(bad, &ignored, {});
        QVERIFY(!ok || !(ignored == r));
    }

    void aReleasedWorkerIsReaped()
    {
        WorkerProcess cat;
        QString error;
        QVERIFY2(cat.start(QStringLiteral("/bin/cat"), &error), qPrintable(error));
        const pid_t pid = cat.pid();
        QVERIFY(alive(pid));
        cat.release(); // cat leaves at the end of its input
        QCOMPARE(cat.isRunning(), false);
        WorkerProcess::waitForReleased();
        QVERIFY(!alive(pid)); // reaped: no zombie
    }
};

QTEST_GUILESS_MAIN(TestLaunchReadAhead)
#include "tst_launchreadahead.moc"
