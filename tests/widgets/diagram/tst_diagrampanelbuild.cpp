// The composed diagram panel on big composites: their layout graph is built off the UI thread
// while the panel says so, a newer request drops a build in flight, closing the panel while a
// build runs is safe, and a graph too big for Graphviz is explained instead of laid out.
#include "diagram/diagramlayouter.h"
#include "support/diagramarchitecture.h"
#include "support/diagramwait.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"

#include <QPointer>
#include <QSignalSpy>
#include <QtTest>

using namespace rosarch;
using rosarch::test::laidOut;

namespace {

/// A fleet of 40 robots: 162 parts and their channels and connections, well over
/// DiagramPanel::kInlineBuildElements.
Architecture bigFleet()
{
    Architecture a;
    a.composites << test::diagram::fleet(40);
    return a;
}

/// A root that starts `count` nodes side by side, in no namespace: even its overview has a
/// box for each.
Architecture wideRoot(int count)
{
    Composite c;
    c.instanceId = QStringLiteral("lf1");
    c.stem = QStringLiteral("wide");
    c.file = QStringLiteral("src/wide/launch/wide.launch.py");
    for (int i = 1; i <= count; ++i)
        c.parts << test::diagram::part(
            QStringLiteral("part%1").arg(i), RosNodePart::Kind::Node, QStringLiteral("n%1").arg(i),
            QStringLiteral("node%1").arg(i), QStringLiteral("Node"), QStringLiteral("/"), {}, i);
    Architecture a;
    a.composites << c;
    return a;
}

int elements(const Composite &c)
{
    return int(c.parts.size() + c.channels.size() + c.boundary.size() + c.connections.size());
}

} // namespace

class TestDiagramPanelBuild : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void bigCompositeIsBuiltOffTheUiThread()
    {
        const Architecture fleet = bigFleet();
        QVERIFY(elements(fleet.composites.first()) > DiagramPanel::kInlineBuildElements);
        DiagramLayouter layouter;
        DiagramPanel panel(&layouter);
        panel.resize(1100, 720);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy finished(&panel, &DiagramPanel::layoutFinished);
        panel.setArchitecture(fleet);
        // setArchitecture returned before the graph was built: the panel says it builds
        QVERIFY(panel.isBuilding());
        QVERIFY(panel.isLayingOut());
        QCOMPARE(panel.view()->busyText(), QStringLiteral("Building diagram…"));
        QVERIFY(finished.isEmpty());
        QVERIFY(laidOut(panel, [] {}));
        QVERIFY(!panel.isBuilding());
        QCOMPARE(panel.message(), QString());
        QCOMPARE(panel.view()->busyText(), QString());
        // 162 parts cannot be read whole in this view: the overview, built on the worker too
        QVERIFY(panel.isCollapsed());
        QVERIFY(panel.isNamespaceCollapsed(QStringLiteral("/robot1")));
        QVERIFY(panel.scene()->item(QStringLiteral("namespace:/robot40")));
        QVERIFY(panel.scene()->item(QStringLiteral("part:part1"))); // the map server, at "/"

        // Expanding a namespace builds again, off the UI thread, and draws its parts.
        panel.setNamespaceCollapsed(QStringLiteral("/robot1"), false);
        QVERIFY(panel.isBuilding());
        QVERIFY(laidOut(panel, [] {}));
        QVERIFY(!panel.isNamespaceCollapsed(QStringLiteral("/robot1")));
        QVERIFY(panel.scene()->item(QStringLiteral("part:part3"))); // robot1's lidar
        QVERIFY(panel.scene()->item(QStringLiteral("namespace:/robot2")));
    }

    void aNewerArchitectureDropsTheBuildInFlight()
    {
        DiagramLayouter layouter;
        DiagramPanel panel(&layouter);
        panel.resize(1100, 720);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.setArchitecture(bigFleet());
        QVERIFY(panel.isBuilding());
        // The document changes while the fleet is built: the hand-made demo replaces it.
        QVERIFY(laidOut(panel, [&] { panel.setArchitecture(test::diagram::architecture()); }));
        QCOMPARE(panel.currentComposite(), QStringLiteral("lf1"));
        QVERIFY(panel.scene()->item(QStringLiteral("channel:q_chatter")));
        // The fleet's build, had it been delivered late, would draw its namespaces.
        QTest::qWait(500);
        QVERIFY(!panel.isLayingOut());
        QVERIFY(panel.scene()->item(QStringLiteral("channel:q_chatter")));
        QVERIFY(!panel.scene()->item(QStringLiteral("namespace:/robot40")));
        QCOMPARE(panel.architecture().composites.size(), 2);
    }

    void closingWhileBuildingIsSafe()
    {
        DiagramLayouter layouter;
        QPointer<DiagramPanel> panel = new DiagramPanel(&layouter);
        panel->resize(1100, 720);
        panel->show();
        QVERIFY(QTest::qWaitForWindowExposed(panel));
        QSignalSpy finished(panel.data(), &DiagramPanel::layoutFinished);
        panel->setArchitecture(bigFleet());
        QVERIFY(panel->isBuilding());
        delete panel; // waits for the worker; its result goes nowhere
        QVERIFY(panel.isNull());
        QTest::qWait(300);
        QVERIFY(finished.isEmpty());
        QVERIFY(!layouter.isRunning()); // no layout was started for the closed panel
    }

    void tooManyBoxesAreExplainedNotLaidOut()
    {
        const int count = DiagramPanel::kMaxLayoutNodes + 50;
        DiagramLayouter layouter;
        DiagramPanel panel(&layouter);
        panel.resize(1100, 720);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QSignalSpy finished(&panel, &DiagramPanel::layoutFinished);
        QVERIFY(laidOut(panel, [&] { panel.setArchitecture(wideRoot(count)); }));
        QCOMPARE(finished.size(), 1);
        QCOMPARE(finished.first().first().toBool(), false);
        QVERIFY(!layouter.isRunning());
        QVERIFY(panel.scene()->isEmpty());
        const QString message = panel.message();
        QVERIFY2(message.startsWith(
                     QStringLiteral("wide has %1 boxes to draw even as an overview").arg(count)),
                 qPrintable(message));
        QVERIFY2(
            message.contains(QStringLiteral("more than %1").arg(DiagramPanel::kMaxLayoutNodes)),
            qPrintable(message));
        QVERIFY(panel.isCollapsed()); // the overview was tried first

        // Expanded, it says so without "even as an overview", and points to the overview.
        QVERIFY(laidOut(panel, [&] { panel.expandAll(); }));
        QVERIFY(!panel.isCollapsed());
        QVERIFY2(panel.message().startsWith(
                     QStringLiteral("wide has %1 boxes to draw; Graphviz would take minutes")
                         .arg(count)),
                 qPrintable(panel.message()));
        QVERIFY(panel.message().contains(QStringLiteral("The overview draws fewer.")));
        QVERIFY(!layouter.isRunning());
    }
};

QTEST_MAIN(TestDiagramPanelBuild)
#include "tst_diagrampanelbuild.moc"
