// The diagram's minimap: where it shows, and that it never covers the current match.
#include "support/diagramshownpanel.h"
#include "widgets/diagram/diagramminimap.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"

#include <QScrollBar>
#include <QtTest>

using namespace rosarch;
using rosarch::test::ShownPanel;

class TestDiagramMinimap : public QObject
{
    Q_OBJECT

private slots:
    void minimapNeverCoversTheMatch();
};

void TestDiagramMinimap::minimapNeverCoversTheMatch()
{
    // Zoomed in on a small view the minimap shows in the bottom-right corner. The panel keeps
    // its current match (the selection) clear of it; a match drawn under that corner sends the
    // minimap to another one, and panning the match away brings it back.
    ShownPanel s;
    QVERIFY(s.ok);
    DiagramPanel &panel = s.panel;
    panel.resize(560, 420);
    panel.view()->setZoom(1.2);
    QCoreApplication::processEvents();
    DiagramMinimap *minimap = panel.view()->minimap();
    QVERIFY2(minimap->isVisible(), "the diagram does not fit: the minimap shows");
    const QRect bottomRight = minimap->geometry();

    panel.selectElement(QStringLiteral("part:part1")); // as a search selects its match
    QCOMPARE(minimap->keepClear(),
             panel.scene()->item(QStringLiteral("part:part1"))->sceneBoundingRect());

    // Somewhere in the drawing, an element drawn under the minimap's corner.
    QScrollBar *h = panel.view()->horizontalScrollBar();
    QScrollBar *v = panel.view()->verticalScrollBar();
    const auto viewRect = [&](const QRectF &sceneRect) {
        return panel.view()->mapFromScene(sceneRect).boundingRect().translated(
            panel.view()->viewport()->geometry().topLeft());
    };
    QString key;
    for (int i = 0; i <= 4 && key.isEmpty(); ++i)
        for (int j = 0; j <= 4 && key.isEmpty(); ++j) {
            h->setValue(h->minimum() + (h->maximum() - h->minimum()) * i / 4);
            v->setValue(v->minimum() + (v->maximum() - v->minimum()) * j / 4);
            for (const QString &k : panel.scene()->keys())
                if (k.startsWith(QLatin1String("part:")) &&
                    viewRect(panel.scene()->item(k)->sceneBoundingRect()).intersects(bottomRight))
                    key = k;
        }
    QVERIFY2(!key.isEmpty(), "an element under the minimap's corner");
    const QRectF matchRect = panel.scene()->item(key)->sceneBoundingRect();
    const auto covered = [&] {
        return minimap->isVisible() && minimap->geometry().intersects(viewRect(matchRect));
    };
    minimap->setKeepClear(matchRect);
    QVERIFY2(!covered(), qPrintable(key));
    QVERIFY(minimap->isVisible());
    QVERIFY(minimap->geometry() != bottomRight); // it moved out of the way
    // Panning the match out of the corner frees it again.
    panel.view()->centerOn(matchRect.center());
    QCoreApplication::processEvents();
    QVERIFY(!covered());
    if (!viewRect(matchRect).intersects(bottomRight))
        QCOMPARE(minimap->geometry(), bottomRight);
}

QTEST_MAIN(TestDiagramMinimap)
#include "tst_diagramminimap.moc"
