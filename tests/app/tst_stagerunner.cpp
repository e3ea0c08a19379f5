#include "app/stagerunner.h"
#include "support/testsupport.h"

#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <atomic>
#include <stdexcept>

using namespace rosarch;

/// StageRunner with injected stages: progress, cancellation, stale results, stage errors.
class TestStageRunner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void runnerCancels()
    {
        StageRunner runner;
        std::atomic<bool> sawCancel{false};
        runner.setStageFunction(
            [&sawCancel](const QString &root, const LaunchOptions &, const StageControl &control) {
                Recovery result;
                result.nodes.workspaceRoot = root;
                for (int i = 0; i < 2000; ++i) {
                    if (control.isCanceled()) {
                        sawCancel = true;
                        result.nodes.canceled = true;
                        return result;
                    }
                    control.report(i, 2000, QStringLiteral("file %1").arg(i));
                    QThread::msleep(5);
                }
                return result;
            });
        QSignalSpy progressed(&runner, &StageRunner::stageProgressed);
        QSignalSpy canceled(&runner, &StageRunner::stageCanceled);
        QSignalSpy finished(&runner, &StageRunner::stageFinished);
        QElapsedTimer timer;
        timer.start();
        runner.run(QStringLiteral("/slow"));
        QVERIFY(runner.isRunning());
        QVERIFY(progressed.wait(5000));
        QCOMPARE(progressed.last().at(1).toInt(), 2000);
        QVERIFY(progressed.last().at(2).toString().startsWith(QStringLiteral("file ")));
        runner.cancel();
        QVERIFY(canceled.wait(5000));
        QVERIFY(sawCancel);
        QVERIFY(timer.elapsed() < 8000); // did not run the 10 s to the end
        QVERIFY(!runner.isRunning());
        QCOMPARE(finished.count(), 0);
    }

    void runnerDropsStaleResults()
    {
        StageRunner runner;
        std::atomic<int> calls{0};
        std::atomic<bool> firstStarted{false};
        runner.setStageFunction(
            [&](const QString &root, const LaunchOptions &, const StageControl &) {
                ++calls;
                if (root == QLatin1String("/first"))
                    firstStarted = true;
                // The first run ignores cancellation and ends first; its result is stale.
                QThread::msleep(root == QLatin1String("/first") ? 250 : 600);
                Recovery result;
                result.nodes.workspaceRoot = root;
                return result;
            });
        QSignalSpy finished(&runner, &StageRunner::stageFinished);
        QSignalSpy canceled(&runner, &StageRunner::stageCanceled);
        runner.run(QStringLiteral("/first"));
        // Let the first really compute, so its result arrives (first) and must be dropped.
        QTRY_VERIFY_WITH_TIMEOUT(firstStarted.load(), 5000);
        runner.run(QStringLiteral("/second"));
        QCOMPARE(runner.generation(), 2);
        QVERIFY(finished.wait(5000));
        QTest::qWait(200);
        QCOMPARE(calls.load(), 2);
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.first().at(0).value<Recovery>().nodes.workspaceRoot,
                 QStringLiteral("/second"));
        QCOMPARE(canceled.count(), 0); // a superseded run is silent
    }

    void runnerReportsStageErrors()
    {
        StageRunner runner;
        runner.setStageFunction(
            [](const QString &, const LaunchOptions &, const StageControl &) -> Recovery {
                throw std::runtime_error("boom");
            });
        QSignalSpy finished(&runner, &StageRunner::stageFinished);
        runner.run(QStringLiteral("/broken"));
        QVERIFY(finished.wait(5000));
        const AtomicNodeList list = finished.first().at(0).value<Recovery>().nodes;
        QCOMPARE(list.workspaceRoot, QStringLiteral("/broken"));
        QCOMPARE(list.diagnostics.size(), 1);
        QCOMPARE(list.diagnostics.first().severity, Diagnostic::Severity::Error);
        QVERIFY(list.diagnostics.first().message.contains(QStringLiteral("boom")));

        // stage 2 alone reports its own failure as a stage 2 diagnostic
        runner.setLaunchFunction(
            [](const QString &, const AtomicNodeList &, const LaunchOptions &,
               const StageControl &) -> LaunchDependencies { throw std::runtime_error("bang"); });
        QSignalSpy launchFinished(&runner, &StageRunner::launchStageFinished);
        runner.runLaunch(QStringLiteral("/broken"), list, {});
        QVERIFY(launchFinished.wait(5000));
        const LaunchDependencies launch = launchFinished.first().at(0).value<LaunchDependencies>();
        QCOMPARE(launch.diagnostics.size(), 1);
        QVERIFY(launch.diagnostics.first().message.contains(QStringLiteral("Stage 2")));
        QVERIFY(launch.diagnostics.first().message.contains(QStringLiteral("bang")));
    }

    void launchOnlyRunGetsNodesAndOptions()
    {
        StageRunner runner;
        std::atomic<int> fullRuns{0};
        runner.setStageFunction([&](const QString &, const LaunchOptions &, const StageControl &) {
            ++fullRuns;
            return Recovery();
        });
        AtomicNodeList seenNodes;
        LaunchOptions seenOptions;
        QString seenRoot;
        runner.setLaunchFunction([&](const QString &root, const AtomicNodeList &nodes,
                                     const LaunchOptions &options, const StageControl &control) {
            seenRoot = root;
            seenNodes = nodes;
            seenOptions = options;
            control.report(1, 2, QStringLiteral("reading bringup.launch.py"));
            LaunchDependencies d;
            d.launchFiles = {QStringLiteral("src/a/launch/bringup.launch.py")};
            return d;
        });
        AtomicNodeList nodes;
        nodes.workspaceRoot = QStringLiteral("/ws");
        AtomicNode n;
        n.id = QStringLiteral("arc_1");
        nodes.nodes = {n};
        LaunchOptions options;
        options.rootFile = QStringLiteral("src/a/launch/bringup.launch.py");
        options.arguments = {{QStringLiteral("robot"), QStringLiteral("r2")}};
        QSignalSpy started(&runner, &StageRunner::stageStarted);
        QSignalSpy finished(&runner, &StageRunner::launchStageFinished);
        QSignalSpy fullFinished(&runner, &StageRunner::stageFinished);
        runner.runLaunch(QStringLiteral("/ws"), nodes, options);
        QCOMPARE(started.count(), 1);
        QCOMPARE(started.first().at(1).value<StageRunner::Job>(), StageRunner::Job::LaunchOnly);
        QCOMPARE(runner.currentJob(), StageRunner::Job::LaunchOnly);
        QVERIFY(finished.wait(5000));
        QCOMPARE(seenRoot, QStringLiteral("/ws"));
        QCOMPARE(seenNodes.nodes.size(), 1);
        QCOMPARE(seenOptions, options);
        QCOMPARE(finished.first().at(0).value<LaunchDependencies>().launchFiles.size(), 1);
        QCOMPARE(fullFinished.count(), 0);
        QCOMPARE(fullRuns.load(), 0);
    }

    void defaultStageRunsStagesOneAndTwo()
    {
        StageRunner runner;
        QSignalSpy started(&runner, &StageRunner::stageStarted);
        QSignalSpy finished(&runner, &StageRunner::stageFinished);
        const QString root = QFileInfo(test::dataDir(QStringLiteral("gui_ws"))).canonicalFilePath();
        runner.run(root);
        QCOMPARE(started.count(), 1);
        QCOMPARE(started.first().at(0).toString(), root);
        QVERIFY(finished.wait(60000));
        const Recovery result = finished.first().at(0).value<Recovery>();
        QCOMPARE(result.nodes.nodes.size(), 2);
        QCOMPARE(result.nodes.packages.size(), 2);
        QCOMPARE(started.first().at(1).value<StageRunner::Job>(), StageRunner::Job::Recovery);
    }
};

QTEST_GUILESS_MAIN(TestStageRunner)
#include "tst_stagerunner.moc"
