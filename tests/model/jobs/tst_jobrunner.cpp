// The one runner for background work: results come back on the runner's thread, a newer job
// drops an older one's result, cancel reaches the job through its token, progress and log
// lines arrive before the result, and no worker outlives the runner.
#include "jobs/jobrunner.h"

#include <QSemaphore>
#include <QSignalSpy>
#include <QThread>
#include <QtTest>

#include <atomic>
#include <stdexcept>

using namespace rosarch;

class TestJobRunner : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void resultArrivesOnTheRunnersThread()
    {
        JobRunner runner;
        QSignalSpy logged(&runner, &JobRunner::logged);
        QSignalSpy progressed(&runner, &JobRunner::progressed);
        int result = 0;
        bool wasCanceled = true;
        QThread *thread = nullptr;
        QStringList order;
        connect(&runner, &JobRunner::logged, this, [&](const QString &l) { order << l; });
        const int generation = runner.start<int>(
            [](const JobControl &control) {
                control.log(QStringLiteral("one"));
                control.progress(1, 2, QStringLiteral("half"));
                control.log(QStringLiteral("two"));
                return 42;
            },
            [&](int r, bool canceled) {
                result = r;
                wasCanceled = canceled;
                thread = QThread::currentThread();
                order << QStringLiteral("done");
            });
        QCOMPARE(generation, 1);
        QVERIFY(runner.isRunning());
        QTRY_COMPARE(result, 42);
        QVERIFY(!wasCanceled);
        QCOMPARE(thread, QThread::currentThread());
        QVERIFY(!runner.isRunning());
        QCOMPARE(order, (QStringList{QStringLiteral("one"), QStringLiteral("two"),
                                     QStringLiteral("done")}));
        QVERIFY(!progressed.isEmpty());
        QCOMPARE(progressed.last().at(2).toString(), QStringLiteral("half"));
    }

    void eachStepShowsItsLastReportWhenStepsEndBetweenDeliveries()
    {
        // Before: only the latest report reached the window, so a stage that finished between
        // two deliveries (a fast stage 2) never showed its progress at all.
        JobRunner runner;
        QList<std::pair<int, qint64>> shown; // step, done
        connect(&runner, &JobRunner::progressed, this,
                [&](qint64 done, qint64, const QString &, int step) {
                    shown.append({step, done});
                });
        bool finished = false;
        // All reports are made before the runner's thread delivers any: the job runs while
        // this thread does not process events.
        QSemaphore made;
        runner.start<int>(
            [&made](const JobControl &control) {
                for (int step = 1; step <= 3; ++step)
                    for (int i = 1; i <= 10; ++i)
                        control.progress(i, 10, QStringLiteral("file %1").arg(i), step);
                made.release();
                return 0;
            },
            [&](int, bool) { finished = true; });
        QVERIFY(made.tryAcquire(1, 10000));
        QTRY_VERIFY(finished);
        QCOMPARE(shown.size(), 3);
        for (int step = 1; step <= 3; ++step)
            QCOMPARE(shown.at(step - 1), (std::pair<int, qint64>{step, 10}));
    }

    void aNewerJobDropsTheOlderResult()
    {
        JobRunner runner;
        QSemaphore release;
        std::atomic_bool olderSawCancel{false};
        QList<int> results;
        runner.start<int>(
            [&](const JobControl &control) {
                release.acquire();
                olderSawCancel = control.isCanceled();
                return 1;
            },
            [&](int r, bool) { results << r; });
        runner.start<int>([](const JobControl &) { return 2; }, [&](int r, bool) { results << r; });
        QCOMPARE(runner.generation(), 2);
        QTRY_COMPARE(results, QList<int>{2});
        release.release();
        QTRY_VERIFY(olderSawCancel.load());
        QTest::qWait(50); // the older job's end is processed and dropped
        QCOMPARE(results, QList<int>{2});
    }

    void cancelReachesTheJobAndItsResultSaysSo()
    {
        JobRunner runner;
        int seen = -1;
        bool wasCanceled = false;
        bool doneCalled = false;
        runner.start<int>(
            [](const JobControl &control) {
                int polls = 0;
                while (!control.isCanceled() && polls < 10000) {
                    QThread::msleep(1);
                    ++polls;
                }
                return control.cancelFlag()->load() ? 7 : 0;
            },
            [&](int r, bool canceled) {
                seen = r;
                wasCanceled = canceled;
                doneCalled = true;
            });
        runner.cancel();
        QTRY_VERIFY(doneCalled);
        QCOMPARE(seen, 7); // a canceled job may still hand back what it has
        QVERIFY(wasCanceled);
    }

    void aThrowingJobReportsFailure()
    {
        JobRunner runner;
        QSignalSpy failed(&runner, &JobRunner::failed);
        bool doneCalled = false;
        runner.start<int>(
            [](const JobControl &) -> int { throw std::runtime_error("broken input"); },
            [&](int, bool) { doneCalled = true; });
        QVERIFY(failed.wait(5000));
        QCOMPARE(failed.first().first().toString(), QStringLiteral("broken input"));
        QTest::qWait(20);
        QVERIFY(!doneCalled);
    }

    void noWorkerOutlivesTheRunner()
    {
        std::atomic_bool finished{false};
        std::atomic_bool sawCancel{false};
        bool doneCalled = false;
        {
            JobRunner runner;
            runner.start<int>(
                [&](const JobControl &control) {
                    while (!control.isCanceled())
                        QThread::msleep(1);
                    sawCancel = true;
                    QThread::msleep(50);
                    finished = true;
                    return 0;
                },
                [&](int, bool) { doneCalled = true; });
            QThread::msleep(20);
        }
        QVERIFY(sawCancel.load());
        QVERIFY(finished.load()); // the destructor waited for the worker
        QCoreApplication::processEvents();
        QVERIFY(!doneCalled);
    }
};

QTEST_GUILESS_MAIN(TestJobRunner)
#include "tst_jobrunner.moc"
