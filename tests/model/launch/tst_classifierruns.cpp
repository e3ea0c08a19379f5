// Stage 2's runs of each launch file on its own, made on pool threads and merged: whatever the
// number of threads and the order the pool ran them in, the result is the one of one executor
// running the files one after the other (ids, containers named in earlier files, the budget's
// cut), and a cancel ends them.
#include "cache/analysiscache.h"
#include "core/rosnames.h"
#include "executorfixture.h"
#include "launch/classifierruns.h"
#include "launch/launchanalyzer.h"
#include "launch/launchexecutor.h"
#include "pipeline/recovery.h"
#include "support/testsupport.h"
#include "workspace/workspacescanner.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QThread>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>
#include <QtTest>

#include <algorithm>
#include <atomic>

using namespace rosarch;
using test::PoolSize;
using namespace rosarch::test::executor;

namespace {

LaunchAction composable(const QString &name)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::ComposableNode;
    a.package = lit(QStringLiteral("demo"));
    a.plugin = lit(QStringLiteral("demo::Filter"));
    a.name = lit(name);
    return a;
}

LaunchAction container(const QString &name, const QString &child)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::ComposableContainer;
    a.package = lit(QStringLiteral("rclcpp_components"));
    a.executable = lit(QStringLiteral("component_container"));
    a.name = lit(name);
    a.children << composable(child);
    return a;
}

LaunchAction load(const QString &target, const QStringList &children)
{
    LaunchAction a;
    a.kind = LaunchAction::Kind::LoadComposableNodes;
    a.target = lit(target);
    for (const QString &c : children)
        a.children << composable(c);
    return a;
}

LaunchAction pushed(const QString &ns, QList<LaunchAction> children)
{
    LaunchAction push;
    push.kind = LaunchAction::Kind::PushNamespace;
    push.nameSpace = lit(ns);
    LaunchAction group;
    group.kind = LaunchAction::Kind::Group;
    group.scoped = true;
    group.children = QList<LaunchAction>{push} + children;
    return group;
}

const QString kA = QStringLiteral("bringup/launch/a.launch.py");
const QString kB = QStringLiteral("bringup/launch/b.launch.py");
const QString kC = QStringLiteral("bringup/launch/c.launch.py");
const QString kD = QStringLiteral("bringup/launch/d.launch.py");
const QString kE = QStringLiteral("bringup/launch/e.launch.py");

/// Five files: containers named "shared" in a and c, loads into "shared" in b, d and e (e
/// includes a, so finds it in its own run), a load into a container no file declares.
void addFiles(Fixture &fx)
{
    fx.add(kA, {node(QStringLiteral("demo"), QStringLiteral("talker"), QStringLiteral("t"), 1),
                container(QStringLiteral("shared"), QStringLiteral("first"))});
    fx.add(kB, {load(QStringLiteral("shared"), {QStringLiteral("late"), QStringLiteral("later")}),
                load(QStringLiteral("nowhere"), {QStringLiteral("lost")})});
    fx.add(kC, {pushed(QStringLiteral("robot"),
                       {container(QStringLiteral("shared"), QStringLiteral("second"))})});
    fx.add(kD, {pushed(QStringLiteral("robot"),
                       {load(QStringLiteral("shared"), {QStringLiteral("latest")})})});
    fx.add(kE, {include(share(QStringLiteral("bringup"), QStringLiteral("launch/a.launch.py"))),
                load(QStringLiteral("shared"), {QStringLiteral("own")})});
}

LaunchExecutor::Loader loaderOf(const Fixture &fx)
{
    return [&fx](const QString &f) -> const LaunchFileDescription * {
        const auto it = fx.files.constFind(f);
        return it == fx.files.constEnd() ? nullptr : &*it;
    };
}

/// What one executor running `files` one after the other makes (stage 2 before its runs were
/// made on pool threads).
LaunchDependencies oneAfterTheOther(const Fixture &fx, const QStringList &files, qsizetype budget)
{
    LaunchDependencies alone;
    LaunchDependencies out;
    LaunchExecutor executor(fx.ws, fx.nodes, loaderOf(fx), &alone);
    executor.setIdPrefix(QStringLiteral("c"));
    for (const QString &file : files) {
        if (alone.instances.size() + alone.nodes.size() > budget) {
            Diagnostic d;
            d.code = QStringLiteral("launch-evaluation-limit");
            d.message = QStringLiteral("Analysing each launch file on its own for its diagram "
                                       "stopped after %1 instances; the diagrams of %2 and later "
                                       "files show them as included by the system.")
                            .arg(budget)
                            .arg(file);
            d.evidence = Evidence::startOf(file);
            out.diagnostics.append(d);
            break;
        }
        executor.runRoot(file, {}, QLatin1String(RosNames::kClassifierScope));
    }
    out.classifierInstances = alone.instances;
    out.classifierNodes = alone.nodes;
    return out;
}

LaunchDependencies onThePool(const Fixture &fx, const QStringList &files, qsizetype budget,
                             const QStringList &begun, const StageControl &control = {})
{
    LaunchDependencies out;
    ClassifierRuns runs(fx.ws, fx.nodes, loaderOf(fx), control, budget);
    if (!begun.isEmpty())
        runs.start(begun);
    runs.finish(files, &out);
    return out;
}

const NodeInstance *named(const LaunchDependencies &d, const QString &name, const QString &file)
{
    for (const NodeInstance &n : d.classifierNodes)
        if (n.nodeName == name)
            for (const LaunchFileInstance &i : d.classifierInstances)
                if (i.id == n.launchFileId && i.file == file)
                    return &n;
    return nullptr;
}

} // namespace

class TestClassifierRuns : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void sameAsOneExecutorOnAnyNumberOfThreads_data()
    {
        QTest::addColumn<QStringList>("files");
        QTest::addColumn<QStringList>("begun");
        const QStringList order{kA, kB, kC, kD, kE};
        QStringList reversed = order;
        std::reverse(reversed.begin(), reversed.end());
        QTest::newRow("nothing begun") << order << QStringList();
        QTest::newRow("begun in order") << order << order;
        QTest::newRow("begun reversed") << order << reversed;
        QTest::newRow("begun in part") << order << QStringList{kE, kC};
        QTest::newRow("another order") << reversed << order;
        QTest::newRow("a file no one has") << QStringList{kD, QStringLiteral("x.py"), kA} << order;
    }
    void sameAsOneExecutorOnAnyNumberOfThreads()
    {
        QFETCH(QStringList, files);
        QFETCH(QStringList, begun);
        Fixture fx;
        addFiles(fx);
        const LaunchDependencies expected = oneAfterTheOther(fx, files, ClassifierRuns::kBudget);
        QVERIFY(!expected.classifierNodes.isEmpty());
        for (const int threads : {1, 2, 4, 8})
            for (int run = 0; run < 5; ++run) {
                const PoolSize size(threads);
                const LaunchDependencies d = onThePool(fx, files, ClassifierRuns::kBudget, begun);
                QVERIFY(d.classifierInstances == expected.classifierInstances);
                QVERIFY(d.classifierNodes == expected.classifierNodes);
                QVERIFY(d.diagnostics.isEmpty());
            }
    }

    void containersNamedInEarlierFilesAreFound()
    {
        Fixture fx;
        addFiles(fx);
        const PoolSize size(4);
        const LaunchDependencies d =
            onThePool(fx, {kA, kB, kC, kD, kE}, ClassifierRuns::kBudget, {kE, kD, kC, kB, kA});
        const NodeInstance *inA = named(d, QStringLiteral("shared"), kA);
        const NodeInstance *inC = named(d, QStringLiteral("shared"), kC);
        QVERIFY(inA && inC);
        QCOMPARE(inA->id, QStringLiteral("cn2"));
        // b runs after a: its loads find a's container; one into a container no file has keeps
        // the name.
        QCOMPARE(named(d, QStringLiteral("late"), kB)->container, inA->id);
        QCOMPARE(named(d, QStringLiteral("later"), kB)->container, inA->id);
        QCOMPARE(named(d, QStringLiteral("lost"), kB)->container, QStringLiteral("nowhere"));
        // d runs after a and c: the last container of that name wins.
        QCOMPARE(named(d, QStringLiteral("latest"), kD)->container, inC->id);
        // e's own run includes a: the container of its include, not a's run's.
        const NodeInstance *own = named(d, QStringLiteral("own"), kE);
        QVERIFY(own);
        QVERIFY(own->container != inA->id && own->container != inC->id);
        bool found = false;
        for (const NodeInstance &n : d.classifierNodes)
            found = found || (n.id == own->container && n.nodeName == QLatin1String("shared") &&
                              n.launchFileId != inA->launchFileId);
        QVERIFY(found);
    }

    void aContainerIsNamedAsBefore()
    {
        // What the lookup compared before it left out the names of other lengths: the node's
        // name, and its fully qualified name against the target and the scoped target.
        const QStringList names{QString(),
                                QStringLiteral("c"),
                                QStringLiteral(" c "),
                                QStringLiteral("c/"),
                                QStringLiteral("/c"),
                                QStringLiteral("/"),
                                QStringLiteral("/ns/c"),
                                QStringLiteral("ns/c"),
                                QStringLiteral("container"),
                                QStringLiteral("c//")};
        const QStringList spaces{QString(), QStringLiteral("/ns"), QStringLiteral("/ns/inner"),
                                 QStringLiteral("/n")};
        const QStringList targets{QString(),
                                  QStringLiteral("c"),
                                  QStringLiteral("/ns/c"),
                                  QStringLiteral("/c"),
                                  QStringLiteral("c/"),
                                  QStringLiteral("/"),
                                  QStringLiteral(" c"),
                                  QStringLiteral("inner/c"),
                                  QStringLiteral("container")};
        int matched = 0;
        for (const QString &target : targets)
            for (const QString &scope : spaces) {
                const LaunchExecutor::ContainerName name(target, scope);
                for (const QString &nodeName : names)
                    for (const QString &nodeSpace : spaces) {
                        NodeInstance n;
                        n.nodeName = nodeName;
                        n.nameSpace = nodeSpace;
                        const QString fq = joinNamespace(nodeSpace, nodeName);
                        const bool before =
                            !target.isEmpty() && (nodeName == target || fq == target ||
                                                  fq == joinNamespace(scope, target));
                        QVERIFY2(name.matches(n) == before,
                                 qPrintable(QStringLiteral("target '%1' in '%2', node '%3' in '%4'")
                                                .arg(target, scope, nodeName, nodeSpace)));
                        matched += before ? 1 : 0;
                    }
            }
        QVERIFY(matched > 50); // the rows do match, not only miss
    }

    void theBudgetCutsAtTheSameFile_data()
    {
        QTest::addColumn<qsizetype>("budget");
        QTest::addColumn<QString>("cutAt"); // "" = no cut
        // a makes 4 (its instance, the talker, the container, its component), b 4, c 3, d 2
        QTest::newRow("after a") << qsizetype(3) << kB;
        QTest::newRow("at a's size") << qsizetype(4) << kC;
        QTest::newRow("after b") << qsizetype(7) << kC;
        QTest::newRow("after c") << qsizetype(8) << kD;
        QTest::newRow("after d") << qsizetype(12) << kE;
        QTest::newRow("none") << qsizetype(13) << QString();
    }
    void theBudgetCutsAtTheSameFile()
    {
        QFETCH(qsizetype, budget);
        QFETCH(QString, cutAt);
        Fixture fx;
        addFiles(fx);
        const QStringList files{kA, kB, kC, kD, kE};
        const LaunchDependencies expected = oneAfterTheOther(fx, files, budget);
        QCOMPARE(expected.diagnostics.size(), cutAt.isEmpty() ? 0 : 1);
        if (!cutAt.isEmpty())
            QCOMPARE(expected.diagnostics[0].evidence.file, cutAt);
        for (const int threads : {1, 2, 8}) {
            const PoolSize size(threads);
            const LaunchDependencies d = onThePool(fx, files, budget, files);
            QVERIFY(d.classifierInstances == expected.classifierInstances);
            QVERIFY(d.classifierNodes == expected.classifierNodes);
            QVERIFY(d.diagnostics == expected.diagnostics);
        }
    }

    void runsFromAPoolThreadWithNoThreadLeft()
    {
        // Stage 2 may itself run on the pool, which may have no other thread free: the caller
        // runs what no pool thread began, and never waits for a run that has not begun.
        Fixture fx;
        addFiles(fx);
        const QStringList files{kA, kB, kC, kD, kE};
        const LaunchDependencies expected = oneAfterTheOther(fx, files, ClassifierRuns::kBudget);
        for (const int threads : {1, 2}) {
            const PoolSize size(threads);
            QFuture<LaunchDependencies> run = QtConcurrent::run(
                [&] { return onThePool(fx, files, ClassifierRuns::kBudget, {}); });
            QElapsedTimer timer;
            timer.start();
            while (!run.isFinished() && timer.elapsed() < 10000)
                QThread::msleep(5);
            QVERIFY(run.isFinished());
            QVERIFY(run.result().classifierNodes == expected.classifierNodes);
        }
    }

    void aCancelEndsTheRuns()
    {
        Fixture fx;
        addFiles(fx);
        // Many files, so the cancel comes while runs are waiting.
        QStringList files;
        for (int k = 0; k < 200; ++k) {
            const QString file = QStringLiteral("bringup/launch/many%1.launch.py").arg(k);
            fx.add(file,
                   {include(share(QStringLiteral("bringup"), QStringLiteral("launch/e.launch.py"))),
                    container(QStringLiteral("shared"), QStringLiteral("c"))});
            files << file;
        }
        for (const int threads : {1, 2, 8}) {
            const PoolSize size(threads);
            std::atomic<int> entered{0};
            StageControl control;
            control.fileWork = [&](const QString &, bool entering) {
                if (entering)
                    ++entered;
            };
            control.canceled = [&] { return entered.load() >= 20; };
            QElapsedTimer timer;
            timer.start();
            const LaunchDependencies d =
                onThePool(fx, files, ClassifierRuns::kBudget, files, control);
            QVERIFY(timer.elapsed() < 5000);
            QVERIFY(d.classifierInstances.isEmpty()); // as a canceled run always left them
            QVERIFY(d.classifierNodes.isEmpty());
            QVERIFY(entered.load() < 20 + threads + 1); // no run begins after the cancel
        }
    }

    void stageTwoIsTheSameOnAnyNumberOfThreads_data()
    {
        QTest::addColumn<QString>("root");
        for (const char *name : {"compose_system/ws", "launch_formats/ws", "launch_constructs/ws"})
            QTest::newRow(name) << test::dataDir(QString::fromLatin1(name));
    }
    void stageTwoIsTheSameOnAnyNumberOfThreads()
    {
        QFETCH(QString, root);
        AnalysisCache off{QString()};
        StageControl control;
        control.cache = &off;
        const Recovery r = recoverWorkspace(root, {}, control);
        QVERIFY(!r.launch.classifierNodes.isEmpty());
        LaunchDependencies alone;
        {
            const PoolSize one(1);
            alone = analyzeLaunchFiles(root, r.nodes, {}, control);
        }
        QVERIFY(alone == r.launch);
        for (const int threads : {2, 4, 8})
            for (int run = 0; run < 3; ++run) {
                const PoolSize size(threads);
                QVERIFY(analyzeLaunchFiles(root, r.nodes, {}, control) == alone);
            }
    }

    void aResultNotCanceledIsWhole_data() { stageTwoIsTheSameOnAnyNumberOfThreads_data(); }
    void aResultNotCanceledIsWhole()
    {
        // A cancel at any point, the files' own runs included: stage 2 says it was canceled,
        // or gives the whole result, and what it kept in the cache gives the whole result.
        QFETCH(QString, root);
        AnalysisCache off{QString()};
        StageControl plain;
        plain.cache = &off;
        const Recovery r = recoverWorkspace(root, {}, plain);
        int entries = 0;
        plain.fileWork = [&](const QString &, bool entering) { entries += entering ? 1 : 0; };
        const LaunchDependencies whole = analyzeLaunchFiles(root, r.nodes, {}, plain);
        QVERIFY(entries > 2);
        for (int at = 1; at <= entries; ++at) {
            const QTemporaryDir dir;
            AnalysisCache cache(dir.path());
            std::atomic<int> entered{0};
            StageControl control;
            control.cache = &cache;
            control.fileWork = [&](const QString &, bool entering) {
                if (entering)
                    ++entered;
            };
            control.canceled = [&] { return entered.load() >= at; };
            const LaunchDependencies d = analyzeLaunchFiles(root, r.nodes, {}, control);
            QVERIFY2(d.canceled || d == whole, qPrintable(QString::number(at)));
            cache.flush();
            StageControl again;
            again.cache = &cache;
            QVERIFY2(analyzeLaunchFiles(root, r.nodes, {}, again) == whole,
                     qPrintable(QString::number(at)));
        }
    }
};

QTEST_GUILESS_MAIN(TestClassifierRuns)
#include "tst_classifierruns.moc"
