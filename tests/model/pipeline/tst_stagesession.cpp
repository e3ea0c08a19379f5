// A long-lived analysis worker (StageSession): one worker serves run after run and gives what a
// fresh worker gives, also after a file changed between runs; a crash in one file, a cancel or
// an overrun costs that worker, and the next run gets a new one; runs from two threads each get
// their own result; the worker leaves with the session. The faults are the worker's test
// switches (ROSARCH_STAGES_TEST_*), read when a worker starts.
#include "pipeline/recovery.h"
#include "pipeline/stagesession.h"
#include "support/recoverytest.h"
#include "support/testsupport.h"

#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <thread>

using namespace rosarch;
using test::writeFile;

namespace {

/// A Python package with a healthy node `Good` and a second node in `victim.py`.
void twoNodes(const QString &root, const QByteArray &victimClass = "Victim")
{
    test::healthyPythonPackage(root, "victim = pkg.victim:main");
    writeFile(root + "/src/pkg/pkg/victim.py",
              "from rclpy.node import Node\nfrom std_msgs.msg import String\n\nclass " +
                  victimClass +
                  "(Node):\n    def __init__(self):\n        super().__init__('victim')\n"
                  "        self.sub = self.create_subscription(String, 'out', print, 10)\n");
}

class Fault
{
public:
    Fault(const char *name, const QByteArray &value) : m_name(name) { qputenv(name, value); }
    ~Fault() { qunsetenv(m_name); }

private:
    const char *m_name;
};

bool alive(qint64 pid)
{
    return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno != ESRCH);
}

} // namespace

class TestStageSession : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void theWorkerStartsAheadOfNeedAndServesRunAfterRun()
    {
        const QString ws = test::dataDir(QStringLiteral("compose_system/ws"));
        const Recovery direct = recoverWorkspace(ws);
        StageSession session;
        const qint64 pid = session.workerPid();
        QVERIFY(alive(pid));
        for (int run = 0; run < 3; ++run) {
            const StageProcess::Result r = session.recover(ws, {}, {});
            QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
            QCOMPARE(r.attempts, 1);
            QVERIFY(r.recovery == direct);
        }
        QCOMPARE(session.workerPid(), pid);
        QCOMPARE(session.workersStarted(), 1);
    }

    void anEditBetweenRunsIsSeen()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        StageSession session;
        StageProcess::Result r = session.recover(dir.path(), {}, {});
        QCOMPARE(test::classNames(r.recovery), (QStringList{"Good", "Victim"}));
        twoNodes(dir.path(), "Renamed");
        r = session.recover(dir.path(), {}, {});
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(test::classNames(r.recovery), (QStringList{"Good", "Renamed"}));
        QVERIFY(r.recovery == recoverWorkspace(dir.path()));
        // The stage 2 re-run on the same worker, against the nodes just recovered.
        const StageProcess::Result launch =
            session.launch(dir.path(), r.recovery.nodes, {}, StageControl());
        QVERIFY(launch.recovery.launch == r.recovery.launch);
        QVERIFY(launch.recovery.architecture == r.recovery.architecture);
        QCOMPARE(session.workersStarted(), 1);
    }

    void aCrashInOneFileRestartsTheWorkerWithoutIt()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Fault fault("ROSARCH_STAGES_TEST_CRASH_IN", "victim.py");
        StageSession session;
        const qint64 first = session.workerPid();
        for (int run = 0; run < 2; ++run) {
            const StageProcess::Result r = session.recover(dir.path(), {}, {});
            QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
            QVERIFY(r.attempts >= 2);
            QCOMPARE(test::classNames(r.recovery), QStringList{QStringLiteral("Good")});
            const QStringList why =
                test::diagnosticsWithCode(r.recovery, QStringLiteral("file-skipped"));
            QCOMPARE(why.size(), 1);
            QVERIFY2(why.first().contains(QLatin1String("the analysis worker crashed")),
                     qPrintable(why.first()));
        }
        QVERIFY(!alive(first));
        QVERIFY(alive(session.workerPid()));
        // The worker that replaced the crashed one serves a healthy workspace in full.
        const QString ws = test::dataDir(QStringLiteral("compose_system/ws"));
        const int started = session.workersStarted();
        const StageProcess::Result healthy = session.recover(ws, {}, {});
        QCOMPARE(healthy.attempts, 1);
        QVERIFY(healthy.recovery == recoverWorkspace(ws));
        QCOMPARE(session.workersStarted(), started);
    }

    void aCanceledRunIsFollowedByAFreshWorker()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Fault fault("ROSARCH_STAGES_TEST_HANG_IN", "victim.py");
        StageSession session;
        const qint64 first = session.workerPid();
        std::atomic_bool cancel = false;
        StageControl control;
        control.canceled = [&] { return cancel.load(); };
        std::thread canceler([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(400));
            cancel = true;
        });
        const StageProcess::Result canceled = session.recover(dir.path(), {}, control);
        canceler.join();
        QVERIFY(canceled.canceled);
        QVERIFY(!alive(first));
        QVERIFY(alive(session.workerPid())); // started again at once, for the next run
        const QString ws = test::dataDir(QStringLiteral("compose_system/ws"));
        const StageProcess::Result next = session.recover(ws, {}, {});
        QVERIFY2(next.error.isEmpty(), qPrintable(next.error));
        QCOMPARE(next.attempts, 1);
        QVERIFY(next.recovery == recoverWorkspace(ws));
    }

    void twoRunsDoNotMixResults()
    {
        const QString a = test::dataDir(QStringLiteral("compose_system/ws"));
        const QString b = test::dataDir(QStringLiteral("launch_constructs"));
        const Recovery directA = recoverWorkspace(a);
        const Recovery directB = recoverWorkspace(b);
        QVERIFY(!(directA == directB));
        StageSession session;
        // Alternating workspaces: each reply is relative to the previous one of the other.
        for (int run = 0; run < 2; ++run) {
            QVERIFY(session.recover(a, {}, {}).recovery == directA);
            QVERIFY(session.recover(b, {}, {}).recovery == directB);
        }
        // Two threads at once take turns.
        StageProcess::Result fromA, fromB;
        std::thread other([&] { fromA = session.recover(a, {}, {}); });
        fromB = session.recover(b, {}, {});
        other.join();
        QVERIFY(fromA.recovery == directA);
        QVERIFY(fromB.recovery == directB);
        QCOMPARE(session.workersStarted(), 1);
    }

    void theWorkerLeavesWithItsSession()
    {
        qint64 pid = -1;
        {
            StageSession session;
            QVERIFY(
                session.recover(test::dataDir(QStringLiteral("py_basic")), {}, {}).error.isEmpty());
            pid = session.workerPid();
            QVERIFY(alive(pid));
        }
        QVERIFY(!alive(pid)); // ended and reaped: no orphan, no zombie
    }

    void aMissingWorkerIsSaidByTheRun()
    {
        StageProcess::Options options;
        options.helperPath = QStringLiteral("/nonexistent/rosarch-stages");
        StageSession session(options);
        QCOMPARE(session.workerPid(), -1);
        const StageProcess::Result r =
            session.recover(test::dataDir(QStringLiteral("py_basic")), {}, {});
        QVERIFY2(r.error.startsWith(QLatin1String(
                     "The analysis worker /nonexistent/rosarch-stages could not be started")),
                 qPrintable(r.error));
    }
};

QTEST_GUILESS_MAIN(TestStageSession)
#include "tst_stagesession.moc"
