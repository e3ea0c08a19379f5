// The window at 1024 x 700: the Log shows more than two findings, and the Log's filter bar shows
// each of its controls whole.
#include "diagnosticfilterbar.h"
#include "guifixture.h"
#include "logview.h"
#include "mainwindow.h"

#include <QAction>
#include <QSettings>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;

class TestSmallWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
    }

    void theLogIsUsableAt1024x700()
    {
        MainWindow w;
        w.show();
        w.resize(1024, 700);
        QTRY_COMPARE(w.height(), 700);
        for (QAction *a : w.findChildren<QAction *>())
            if (a->text() == QStringLiteral("&Reset Layout"))
                a->trigger();
        w.openWorkspace(test::dataDir(QStringLiteral("check_system/ws"))); // five findings
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTreeView *findings = w.logView()->diagnosticsView();
        QTRY_VERIFY(findings->model()->rowCount() >= 3);
        const int rowHeight = findings->sizeHintForRow(0);
        QVERIFY(rowHeight > 0);
        QTRY_VERIFY2(findings->viewport()->height() >= 3 * rowHeight,
                     qPrintable(QStringLiteral("%1 px for rows of %2 px")
                                    .arg(findings->viewport()->height())
                                    .arg(rowHeight)));
        // The filter bar's controls are shown whole, inside the Log.
        const QRect log = w.logView()->rect();
        for (QWidget *child : w.logView()->filterBar()->findChildren<QWidget *>()) {
            if (!child->isVisible() || child->parentWidget() != w.logView()->filterBar())
                continue;
            const QRect at(child->mapTo(w.logView(), QPoint()), child->size());
            QVERIFY2(log.contains(at),
                     qPrintable(child->objectName() + u' ' + child->metaObject()->className()));
            QVERIFY2(child->width() >= child->minimumSizeHint().width(),
                     qPrintable(child->metaObject()->className()));
        }
    }
};

QTEST_MAIN(TestSmallWindow)
#include "tst_smallwindow.moc"
