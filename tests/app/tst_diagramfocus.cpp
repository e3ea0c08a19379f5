// View → Focus Diagram (Ctrl+Shift+D) gives the composed diagram the whole window and gives the
// other panels back as they were; the layout remembered on quitting is the one to come back to.
#include "app/diagramfocus.h"
#include "app/mainwindow.h"
#include "support/guifixture.h"
#include "widgets/diagram/diagrampanel.h"

#include <QAction>
#include <QDockWidget>
#include <QSettings>
#include <QToolBar>
#include <QtTest>

using namespace rosarch;

class TestDiagramFocus : public QObject
{
    Q_OBJECT

    static QStringList visibleDocks(const MainWindow &w)
    {
        QStringList out;
        for (QDockWidget *dock : w.findChildren<QDockWidget *>())
            if (dock->isVisible())
                out << dock->objectName();
        out.sort();
        return out;
    }

private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
    }

    void theDiagramTakesTheWindowAndGivesItBack()
    {
        MainWindow w;
        w.resize(1440, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QApplication::setActiveWindow(&w);
        QDockWidget *diagramDock = w.findChild<QDockWidget *>(QStringLiteral("diagramDock"));
        QVERIFY(diagramDock);
        const QStringList before = visibleDocks(w);
        QVERIFY(before.size() > 3);
        const QSize small = diagramDock->size();
        auto *toolBar = w.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
        QVERIFY(toolBar && toolBar->isVisible());

        QTest::keyClick(&w, Qt::Key_D, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(visibleDocks(w), QStringList{QStringLiteral("diagramDock")});
        QVERIFY(test::child<DiagramFocus>(w)->action()->isChecked());
        QVERIFY(!toolBar->isVisible());
        QTRY_VERIFY(diagramDock->width() > w.width() * 9 / 10);
        QVERIFY(diagramDock->height() > small.height());

        QTest::keyClick(&w, Qt::Key_D, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(visibleDocks(w), before);
        QVERIFY(
            test::child<DiagramPanel>(w)->isAncestorOf(QApplication::focusWidget())); // still there
        QVERIFY(!test::child<DiagramFocus>(w)->action()->isChecked());
        QVERIFY(toolBar->isVisible());
        QTRY_COMPARE(diagramDock->size(), small);

        // Focused when the window closes: what is remembered is the layout with every panel.
        test::child<DiagramFocus>(w)->action()->trigger();
        QTRY_COMPARE(visibleDocks(w), QStringList{QStringLiteral("diagramDock")});
        w.close();
        QVERIFY(!test::child<DiagramFocus>(w)->isFocused());
        MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QTRY_COMPARE(visibleDocks(again), before);
    }
};

QTEST_MAIN(TestDiagramFocus)
#include "tst_diagramfocus.moc"
