// The stages in the analysis worker process (rosarch-stages), supervised by StageProcess: the
// result is the one the stages give in-process, field for field; a crash, a hang or a memory
// blow-up while one file is analysed costs that file alone, with a diagnostic saying why; what
// cannot be pinned on a file is an error, never a crash of the caller. The faults are the
// worker's test switches (ROSARCH_STAGES_TEST_*), a stand-in for analyser bugs nobody has found.
#include "compose/composearchitecture.h"
#include "pipeline/recovery.h"
#include "pipeline/recoverystream.h"
#include "pipeline/stageprocess.h"
#include "support/recoverytest.h"
#include "support/testsupport.h"

#include <QDir>
#include <QTemporaryDir>
#include <QtTest>

#include <atomic>
#include <thread>

using namespace rosarch;
using test::writeFile;

namespace {

/// A Python package with a healthy node `Good` and a second node in `victim.py`.
void twoNodes(const QString &root)
{
    test::healthyPythonPackage(root, "victim = pkg.victim:main");
    writeFile(root + "/src/pkg/pkg/victim.py",
              "from rclpy.node import Node\nfrom std_msgs.msg import String\n\n"
              "class Victim(Node):\n    def __init__(self):\n        super().__init__('victim')\n"
              "        self.sub = self.create_subscription(String, 'out', print, 10)\n");
    writeFile(root + "/src/pkg/launch/both.launch.py",
              "from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n"
              "def generate_launch_description():\n    return LaunchDescription([\n"
              "        Node(package='pkg', executable='good', name='good'),\n"
              "        Node(package='pkg', executable='victim', name='victim')])\n");
}

QStringList classes(const Recovery &r)
{
    return test::classNames(r);
}

QStringList skipped(const Recovery &r)
{
    return test::diagnosticsWithCode(r, QStringLiteral("file-skipped"));
}

/// Sets a worker test switch for the scope of one test.
class Fault
{
public:
    Fault(const char *name, const QByteArray &value) : m_name(name) { qputenv(name, value); }
    ~Fault() { qunsetenv(m_name); }

private:
    const char *m_name;
};

bool sanitized()
{
#if defined(__SANITIZE_ADDRESS__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    return true;
#endif
#endif
    return false;
}

} // namespace

class TestStageProcess : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void theWorkerIsBuilt() { QVERIFY(!StageProcess::helperPath().isEmpty()); }

    void aRecoveryStreamsFieldForField_data()
    {
        QTest::addColumn<QString>("workspace");
        QTest::newRow("check_system") << test::dataDir(QStringLiteral("check_system/ws"));
        QTest::newRow("compose_system") << test::dataDir(QStringLiteral("compose_system/ws"));
        QTest::newRow("launch_constructs") << test::dataDir(QStringLiteral("launch_constructs"));
        QTest::newRow("cpp_helpers") << test::dataDir(QStringLiteral("cpp_helpers/ws"));
    }

    void aRecoveryStreamsFieldForField()
    {
        QFETCH(QString, workspace);
        const Recovery direct = recoverWorkspace(workspace);
        QVERIFY(!direct.nodes.nodes.isEmpty() || !direct.launch.instances.isEmpty());
        QByteArray bytes;
        {
            QDataStream out(&bytes, QIODevice::WriteOnly);
            out.setVersion(stagestream::kStreamVersion);
            stagestream::writeResult(out, direct, {});
        }
        Recovery back;
        QDataStream in(bytes);
        in.setVersion(stagestream::kStreamVersion);
        QVERIFY(stagestream::readResult(in, &back, {}));
        QVERIFY(in.atEnd());
        QVERIFY(back == direct);

        // And through the worker: the same recovery as in this process.
        const StageProcess::Result r =
            StageProcess::recover(workspace, {}, StageControl(), StageProcess::Options());
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(r.attempts, 1);
        QVERIFY(r.recovery.nodes == direct.nodes);
        QVERIFY(r.recovery.launch == direct.launch);
        QVERIFY(r.recovery.architecture == direct.architecture);
    }

    void theLaunchStageRunsAgainstGivenNodes()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Recovery full = recoverWorkspace(dir.path());
        LaunchOptions options;
        options.rootFile = QStringLiteral("src/pkg/launch/both.launch.py");
        const StageProcess::Result r =
            StageProcess::launch(dir.path(), full.nodes, options, StageControl(), {});
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        const LaunchDependencies expected = analyzeLaunchFiles(dir.path(), full.nodes, options);
        QVERIFY(r.recovery.launch == expected);
        QVERIFY(r.recovery.architecture == composeArchitecture(full.nodes, expected));
        QCOMPARE(r.recovery.launch.nodes.size(), 2);

        // In this process the same two stages give the same, and time both.
        QList<int> timed;
        StageControl control;
        control.stageTimed = [&](int stage, qint64) { timed << stage; };
        const Recovery here = recoverLaunch(dir.path(), full.nodes, options, control);
        QVERIFY(here.launch == expected);
        QVERIFY(here.architecture == r.recovery.architecture);
        QVERIFY(!here.architecture.composites.isEmpty());
        QVERIFY(here.nodes.nodes.isEmpty());
        QCOMPARE(timed, (QList<int>{2, 3}));
        // A stage 2 given in its place runs instead; a canceled one leaves stage 3 out.
        int calls = 0;
        const Recovery stood = recoverLaunch(dir.path(), full.nodes, options, {}, nullptr,
                                             [&](const QString &, const AtomicNodeList &,
                                                 const LaunchOptions &, const StageControl &) {
                                                 ++calls;
                                                 LaunchDependencies canceled;
                                                 canceled.canceled = true;
                                                 return canceled;
                                             });
        QCOMPARE(calls, 1);
        QVERIFY(stood.launch.canceled);
        QVERIFY(stood.architecture == Architecture());
    }

    void aCrashInOneFileCostsThatFile()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Fault fault("ROSARCH_STAGES_TEST_CRASH_IN", "victim.py");
        QStringList progress;
        StageControl control;
        control.progressed = [&](int, int, const QString &what) { progress << what; };
        const StageProcess::Result r = StageProcess::recover(dir.path(), {}, control, {});
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QVERIFY(r.attempts >= 2);
        QCOMPARE(classes(r.recovery), QStringList{QStringLiteral("Good")});
        const QStringList why = skipped(r.recovery);
        QCOMPARE(why.size(), 1);
        // SIGSEGV; SIGABRT under AddressSanitizer, which reports the fault and aborts.
        static const QRegularExpression crashed(QStringLiteral(
            R"(^src/pkg/pkg/victim\.py: src/pkg/pkg/victim\.py was not analysed: the analysis worker crashed \(signal (11|6)\) on it)"));
        QVERIFY2(crashed.match(why.first()).hasMatch(), qPrintable(why.first()));
        QVERIFY(progress.contains(
            QStringLiteral("Repeating the analysis without src/pkg/pkg/victim.py…")));
        // The rest of the run went on: the launch file still starts both executables.
        QCOMPARE(r.recovery.launch.nodes.size(), 2);
    }

    void aFileThatOverrunsItsTimeBudgetIsSkipped()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Fault fault("ROSARCH_STAGES_TEST_HANG_IN", "victim.py");
        StageProcess::Options options;
        options.fileTimeoutMs = 1500;
        const StageProcess::Result r = StageProcess::recover(dir.path(), {}, {}, options);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(classes(r.recovery), QStringList{QStringLiteral("Good")});
        const QStringList why = skipped(r.recovery);
        QCOMPARE(why.size(), 1);
        QVERIFY2(why.first().contains(
                     QLatin1String("took longer than the time budget of 1.5 s per file")),
                 qPrintable(why.first()));
    }

    void aFileThatExhaustsTheMemoryBudgetIsSkipped()
    {
        if (sanitized())
            QSKIP("sanitizers reserve the address space a memory budget limits");
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Fault fault("ROSARCH_STAGES_TEST_EXHAUST_IN", "victim.py");
        StageProcess::Options options;
        options.memoryBudgetMb = 1024;
        const StageProcess::Result r = StageProcess::recover(dir.path(), {}, {}, options);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(classes(r.recovery), QStringList{QStringLiteral("Good")});
        const QStringList why = skipped(r.recovery);
        QCOMPARE(why.size(), 1);
        QVERIFY2(
            why.first().contains(QLatin1String("exhausted its memory budget of 1024 MB on it")),
            qPrintable(why.first()));
    }

    void cancelingKillsTheWorker()
    {
        QTemporaryDir dir;
        twoNodes(dir.path());
        const Fault fault("ROSARCH_STAGES_TEST_HANG_IN", "victim.py");
        std::atomic_bool cancel = false;
        StageControl control;
        control.canceled = [&] { return cancel.load(); };
        std::thread canceler([&] {
            std::this_thread::sleep_for(std::chrono::milliseconds(500));
            cancel = true;
        });
        const StageProcess::Result r = StageProcess::recover(dir.path(), {}, control, {});
        canceler.join();
        QVERIFY(r.canceled);
        QVERIFY(r.error.isEmpty());
    }

    void aWorkerThatDiesOutsideAnyFileIsAnError()
    {
        QTemporaryDir bin;
        const QString dying = test::script(bin, QStringLiteral("dying-worker"), "kill -SEGV $$");
        StageProcess::Options options;
        options.helperPath = dying;
        const StageProcess::Result r =
            StageProcess::recover(test::dataDir(QStringLiteral("py_basic")), {}, {}, options);
        QVERIFY(!r.canceled);
        QCOMPARE(r.attempts, 1);
        QVERIFY2(r.error.startsWith(QLatin1String(
                     "The analysis stopped outside the work on any one file, so there is no "
                     "result: the analysis worker crashed (signal 11).")),
                 qPrintable(r.error));
    }

    void aWorkerThatDiesAfterStageOneKeepsStageOne()
    {
        // A worker dying outside any one file: what the stages before the stop finished
        // is kept, with an error that says the rest is missing.
        const Fault fault("ROSARCH_STAGES_TEST_CRASH_AFTER_STAGE", "1");
        const StageProcess::Result r =
            StageProcess::recover(test::dataDir(QStringLiteral("py_basic")), {}, {}, {});
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QVERIFY(!r.recovery.nodes.nodes.isEmpty());
        QVERIFY(r.recovery.launch.nodes.isEmpty());
        const QStringList said =
            test::diagnosticsWithCode(r.recovery, QStringLiteral("analysis-incomplete"));
        QCOMPARE(said.size(), 1);
        QVERIFY2(said.first().contains(QLatin1String("stopped during stage 2")) &&
                     said.first().contains(QLatin1String("crashed (signal")), // 6 under ASan
                 qPrintable(said.first()));
    }

    void aMissingWorkerIsSaid()
    {
        StageProcess::Options options;
        options.helperPath = QStringLiteral("/nonexistent/rosarch-stages");
        const StageProcess::Result r =
            StageProcess::recover(test::dataDir(QStringLiteral("py_basic")), {}, {}, options);
        QVERIFY2(r.error.startsWith(QLatin1String(
                     "The analysis worker /nonexistent/rosarch-stages could not be started")),
                 qPrintable(r.error));
    }
};

QTEST_GUILESS_MAIN(TestStageProcess)
#include "tst_stageprocess.moc"
