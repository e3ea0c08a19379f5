// The diagram's layout job: run off the UI thread on a JobRunner with the real rosarch-layout
// helper, cached by the graph's DOT text so a composite shown again needs no helper, failures
// not cached, and a superseded, canceled or orphaned request never reports.
#include "diagram/diagramlayouter.h"
#include "support/testsupport.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QtTest>

#include <optional>

using namespace rosarch;

namespace {

/// `count` boxes in a row, labelled with `tag` so that graphs of different tags differ.
LayoutGraph chain(int count, const QString &tag = QStringLiteral("n"))
{
    LayoutGraph g;
    for (int i = 0; i < count; ++i) {
        LayoutNode n;
        n.id = n.key = QStringLiteral("%1_%2").arg(tag).arg(i);
        n.label = n.id;
        n.width = 80;
        n.height = 40;
        g.nodes << n;
        if (i > 0) {
            LayoutEdge e;
            e.id = e.key = QStringLiteral("e%1").arg(i);
            e.tail = g.nodes.at(i - 1).id;
            e.head = n.id;
            g.edges << e;
        }
    }
    return g;
}

/// Lays `graph` out and waits for the answer.
std::optional<LayoutResult> layOut(DiagramLayouter &layouter, const LayoutGraph &graph)
{
    std::optional<LayoutResult> result;
    layouter.layout(graph, [&](const LayoutResult &r) { result = r; });
    QElapsedTimer clock;
    clock.start();
    while (!result && clock.elapsed() < 30000)
        QTest::qWait(10);
    return result;
}

} // namespace

class TestDiagramLayouter : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void init() { qunsetenv("ROSARCH_LAYOUT"); }

    void aLayoutIsCachedByItsGraph()
    {
        DiagramLayouter layouter;
        const LayoutGraph graph = chain(3);
        QVERIFY(!layouter.cached(graph));
        const std::optional<LayoutResult> result = layOut(layouter, graph);
        QVERIFY(result);
        QVERIFY2(result->ok, qPrintable(result->error));
        QVERIFY(!layouter.isRunning());

        // An equal graph built again (the same DOT text) is served from the cache.
        const std::optional<LayoutGeometry> cached = layouter.cached(chain(3));
        QVERIFY(cached);
        QCOMPARE(cached->bounds, result->geometry.bounds);
        QCOMPARE(cached->nodes, result->geometry.nodes);
        QVERIFY(!layouter.cached(chain(4)));
        QVERIFY(!layouter.cached(chain(3, QStringLiteral("m"))));
    }

    void aFailedLayoutIsNotCached()
    {
        QTemporaryDir dir;
        qputenv("ROSARCH_LAYOUT",
                test::script(dir, QStringLiteral("abort.sh"), "kill -ABRT $$").toLocal8Bit());
        DiagramLayouter layouter;
        const std::optional<LayoutResult> result = layOut(layouter, chain(2));
        QVERIFY(result);
        QVERIFY(!result->ok);
        QVERIFY2(result->error.startsWith(QLatin1String("Graphviz crashed")),
                 qPrintable(result->error));
        QVERIFY(!layouter.cached(chain(2))); // the next request tries again
    }

    void aSupersededRequestDoesNotReport()
    {
        DiagramLayouter layouter;
        QStringList reported;
        layouter.layout(chain(2), [&](const LayoutResult &) { reported << QStringLiteral("2"); });
        layouter.layout(chain(5), [&](const LayoutResult &) { reported << QStringLiteral("5"); });
        QTRY_VERIFY_WITH_TIMEOUT(!layouter.isRunning(), 30000);
        QTest::qWait(50); // the first job's end, if it were to report
        QCOMPARE(reported, QStringList{QStringLiteral("5")});
        QVERIFY(layouter.cached(chain(5)));
    }

    void aCanceledRequestDoesNotReportNorCache()
    {
        DiagramLayouter layouter;
        bool reported = false;
        layouter.layout(chain(3), [&](const LayoutResult &) { reported = true; });
        layouter.cancel();
        QTRY_VERIFY_WITH_TIMEOUT(!layouter.isRunning(), 30000);
        QTest::qWait(50);
        QVERIFY(!reported);
        QVERIFY(!layouter.cached(chain(3)));
    }

    void theCacheKeepsTheLatestLayouts()
    {
        DiagramLayouter layouter;
        QVERIFY(layOut(layouter, chain(2, QStringLiteral("first"))));
        for (int i = 0; i < 40; ++i) {
            const std::optional<LayoutResult> r = layOut(layouter, chain(2, QString::number(i)));
            QVERIFY(r && r->ok);
        }
        QVERIFY(!layouter.cached(chain(2, QStringLiteral("first")))); // bounded: oldest go
        QVERIFY(layouter.cached(chain(2, QStringLiteral("39"))));
    }

    void destroyingTheLayouterStopsTheHelper()
    {
        QTemporaryDir dir;
        qputenv("ROSARCH_LAYOUT",
                test::script(dir, QStringLiteral("slow.sh"), "exec sleep 30").toLocal8Bit());
        bool reported = false;
        QElapsedTimer clock;
        clock.start();
        {
            DiagramLayouter layouter;
            layouter.layout(chain(2), [&](const LayoutResult &) { reported = true; });
            QTest::qWait(200); // the helper is running
            QVERIFY(layouter.isRunning());
        }
        // The destructor killed the helper and waited for the job, well before its 30 s.
        QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
        QCoreApplication::processEvents();
        QVERIFY(!reported);
    }
};

QTEST_GUILESS_MAIN(TestDiagramLayouter)
#include "tst_diagramlayouter.moc"
