#include "stagerunner.h"
#include "testsupport.h"

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
        runner.setStageFunction([&sawCancel](const QString &root, const StageControl &control) {
            AtomicNodeList list;
            list.workspaceRoot = root;
            for (int i = 0; i < 2000; ++i) {
                if (control.isCanceled()) {
                    sawCancel = true;
                    list.canceled = true;
                    return list;
                }
                control.report(i, 2000, QStringLiteral("file %1").arg(i));
                QThread::msleep(5);
            }
            return list;
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
        runner.setStageFunction([&](const QString &root, const StageControl &) {
            ++calls;
            if (root == QLatin1String("/first"))
                firstStarted = true;
            // The first run ignores cancellation and ends first; its result is stale.
            QThread::msleep(root == QLatin1String("/first") ? 250 : 600);
            AtomicNodeList list;
            list.workspaceRoot = root;
            return list;
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
        QCOMPARE(finished.first().at(0).value<AtomicNodeList>().workspaceRoot,
                 QStringLiteral("/second"));
        QCOMPARE(canceled.count(), 0); // a superseded run is silent
    }

    void runnerReportsStageErrors()
    {
        StageRunner runner;
        runner.setStageFunction([](const QString &, const StageControl &) -> AtomicNodeList {
            throw std::runtime_error("boom");
        });
        QSignalSpy finished(&runner, &StageRunner::stageFinished);
        runner.run(QStringLiteral("/broken"));
        QVERIFY(finished.wait(5000));
        const AtomicNodeList list = finished.first().at(0).value<AtomicNodeList>();
        QCOMPARE(list.diagnostics.size(), 1);
        QCOMPARE(list.diagnostics.first().severity, Diagnostic::Severity::Error);
        QVERIFY(list.diagnostics.first().message.contains(QStringLiteral("boom")));
    }

    void defaultStageRunsStageOne()
    {
        StageRunner runner;
        QSignalSpy started(&runner, &StageRunner::stageStarted);
        QSignalSpy finished(&runner, &StageRunner::stageFinished);
        const QString root = QFileInfo(test::dataDir(QStringLiteral("gui_ws"))).canonicalFilePath();
        runner.run(root);
        QCOMPARE(started.count(), 1);
        QCOMPARE(started.first().at(0).toString(), root);
        QVERIFY(finished.wait(60000));
        const AtomicNodeList list = finished.first().at(0).value<AtomicNodeList>();
        QCOMPARE(list.nodes.size(), 2);
        QCOMPARE(list.packages.size(), 2);
    }
};

QTEST_GUILESS_MAIN(TestStageRunner)
#include "tst_stagerunner.moc"
