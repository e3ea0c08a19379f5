// The main window's layout: what it looks like at a laptop's size, and what it remembers.
#include "app/appsettings.h"
#include "app/mainwindow.h"
#include "support/guifixture.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/logview.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLineEdit>
#include <QSettings>
#include <QSortFilterProxyModel>
#include <QToolButton>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;

namespace {

/// View → Reset Layout, found by its text as a person finds it; false when it is missing.
bool resetLayout(MainWindow &w)
{
    for (QAction *a : w.findChildren<QAction *>())
        if (a->text() == QStringLiteral("&Reset Layout")) {
            a->trigger();
            return true;
        }
    return false;
}

} // namespace

class TestWindowLayout : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
    }

    void theWindowFitsALaptopScreen()
    {
        // Before: the Log's filter bar kept its dock ~1,100 px wide, and the window, opened
        // on a 1,440 px wide screen, was wider than it (its right-hand docks cut off).
        MainWindow w;
        w.show();
        w.openWorkspace(QStringLiteral(ROSARCH_EXAMPLE_WORKSPACE));
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY2(w.minimumSizeHint().width() <= 1366,
                 qPrintable(QString::number(w.minimumSizeHint().width())));
        w.resize(1366, 768);
        QTRY_COMPARE(w.width(), 1366);
    }

    void theLogShowsSeveralFindingsInTheDefaultLayout()
    {
        // Before: in the default layout of a 1,440 x 900 window the explanation pane under
        // the findings asked for as much height as the table, which showed one row.
        MainWindow w;
        w.show();
        w.resize(1440, 900);
        QTRY_COMPARE(w.height(), 900);
        QVERIFY(resetLayout(w));
        w.openWorkspace(test::dataDir(QStringLiteral("check_system/ws"))); // five findings
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTreeView *findings = test::child<LogView>(w)->diagnosticsView();
        QTRY_VERIFY(findings->model()->rowCount() >= 3);
        const int rowHeight = findings->sizeHintForRow(0);
        QVERIFY(rowHeight > 0);
        QTRY_VERIFY2(findings->viewport()->height() >= 3 * rowHeight,
                     qPrintable(QStringLiteral("%1 px for rows of %2 px")
                                    .arg(findings->viewport()->height())
                                    .arg(rowHeight)));
    }

    void layoutIsRestored()
    {
        {
            MainWindow w;
            w.show();
            QDockWidget *log = w.findChild<QDockWidget *>(QStringLiteral("logDock"));
            QVERIFY(log);
            log->hide();
            w.close();
        }
        MainWindow again;
        again.show();
        QDockWidget *log = again.findChild<QDockWidget *>(QStringLiteral("logDock"));
        QVERIFY(log && !log->isVisible());
        QVERIFY(again.findChild<QDockWidget *>(QStringLiteral("sourceDock"))->isVisible());
        QVERIFY(resetLayout(again));
        QVERIFY(log->isVisible());
        // A floated Log comes back into the window, in front of the tabs sharing its place.
        log->setFloating(true);
        QVERIFY(log->isFloating());
        QVERIFY(resetLayout(again));
        QVERIFY(!log->isFloating());
        QVERIFY(log->isVisible());
        const QList<QDockWidget *> sharing = again.tabifiedDockWidgets(log);
        QVERIFY(!sharing.isEmpty());
        for (QDockWidget *other : sharing)
            QVERIFY2(other->visibleRegion().isEmpty(), qPrintable(other->objectName()));
    }

    void aLayoutSavedInALargeWindowIsNotForcedOnASmallOne()
    {
        // Before: a layout saved at 1600 x 1000 (Suggestions beside the Log) came back in a
        // 1024 x 700 window, cramped, until Reset Layout.
        QByteArray smallGeometry;
        {
            MainWindow w;
            w.show();
            w.resize(1024, 700);
            QTRY_COMPARE(w.height(), 700);
            smallGeometry = w.saveGeometry();
            w.resize(1600, 1000);
            QTRY_COMPARE(w.height(), 1000);
            QVERIFY(resetLayout(w));
            QDockWidget *log = w.findChild<QDockWidget *>(QStringLiteral("logDock"));
            QVERIFY(log && !w.tabifiedDockWidgets(log).contains(w.findChild<QDockWidget *>(
                               QStringLiteral("suggestionsDock")))); // beside it
            w.close();
        }
        AppSettings().setWindowGeometry(smallGeometry); // the same person, on a laptop
        MainWindow again;
        again.show();
        QTRY_COMPARE(again.height(), 700);
        QDockWidget *log = again.findChild<QDockWidget *>(QStringLiteral("logDock"));
        QDockWidget *suggestions =
            again.findChild<QDockWidget *>(QStringLiteral("suggestionsDock"));
        QVERIFY(log && suggestions);
        QVERIFY(again.tabifiedDockWidgets(log).contains(suggestions)); // the small layout
        // and a layout saved in a window of this size is kept
        suggestions->hide();
        again.close();
        MainWindow third;
        third.show();
        QTRY_COMPARE(third.height(), 700);
        QVERIFY(!third.findChild<QDockWidget *>(QStringLiteral("suggestionsDock"))->isVisible());
    }

    void logFilterIsRemembered()
    {
        {
            MainWindow w;
            w.show();
            DiagnosticFilterBar *bar = test::child<LogView>(w)->filterBar();
            bar->severityButton(Diagnostic::Severity::Info)->setChecked(false);
            bar->searchEdit()->setText(QStringLiteral("braces"));
            bar->groupingCombo()->setCurrentIndex(
                bar->groupingCombo()->findData(int(DiagnosticModel::Grouping::Package)));
            w.close();
        }
        MainWindow again;
        again.show();
        DiagnosticFilterBar *bar = test::child<LogView>(again)->filterBar();
        QVERIFY(!bar->severityButton(Diagnostic::Severity::Info)->isChecked());
        QVERIFY(bar->severityButton(Diagnostic::Severity::Error)->isChecked());
        QCOMPARE(bar->searchEdit()->text(), QStringLiteral("braces"));
        QCOMPARE(bar->groupingCombo()->currentData().toInt(),
                 int(DiagnosticModel::Grouping::Package));
        // and the table follows what the bar says
        const auto *model = qobject_cast<const DiagnosticModel *>(
            qobject_cast<QSortFilterProxyModel *>(
                test::child<LogView>(again)->diagnosticsView()->model())
                ->sourceModel());
        QVERIFY(model);
        QVERIFY(!model->filter().infos);
        QCOMPARE(model->filter().text, QStringLiteral("braces"));
        QCOMPARE(model->grouping(), DiagnosticModel::Grouping::Package);
        bar->restoreState({{QStringLiteral("infos"), true}}); // back to all for the next tests
        again.close();
    }
};

QTEST_MAIN(TestWindowLayout)
#include "tst_windowlayout.moc"
