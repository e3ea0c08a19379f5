// The window at 1024 x 700: the Log shows more than two findings, and the Log's filter bar shows
// each of its controls whole; the diagram's header and toolbars, the main toolbar and the two
// trees are shown whole, nothing behind a toolbar's arrow and no name drawn over another.
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagram/diagrambreadcrumbbar.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramrootpicker.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"

#include <QAction>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;

namespace {

/// The window at 1024 x 700 in the layout Reset Layout gives it.
void smallWindow(MainWindow &w)
{
    w.show();
    w.resize(1024, 700);
    QTRY_COMPARE(w.height(), 700);
    for (QAction *a : w.findChildren<QAction *>())
        if (a->text() == QStringLiteral("&Reset Layout"))
            a->trigger();
}

/// Where `child` is in `in` (its own coordinates).
QRect placeIn(const QWidget *child, const QWidget *in)
{
    return {child->mapTo(in, QPoint()), child->size()};
}

/// No toolbar under `parent` hides an action behind its arrow, and each shows its buttons
/// whole inside `parent`.
QString toolBarProblem(const QWidget *parent,
                       Qt::FindChildOptions options = Qt::FindChildrenRecursively)
{
    for (const QToolBar *bar : parent->findChildren<QToolBar *>(QString(), options)) {
        if (!bar->isVisible())
            continue;
        for (const QWidget *child : bar->findChildren<QWidget *>()) {
            if (child->objectName() == QLatin1String("qt_toolbarext_button")) {
                if (child->isVisible())
                    return bar->windowTitle() + QStringLiteral(": actions behind the arrow");
                continue;
            }
            if (!child->isVisible() || child->parentWidget() != bar)
                continue;
            if (!parent->rect().contains(placeIn(child, parent)))
                return QStringLiteral("%1 %2 outside %3 at %4,%5 %6x%7")
                    .arg(QString::fromLatin1(child->metaObject()->className()),
                         child->property("text").toString(), bar->windowTitle())
                    .arg(placeIn(child, parent).x())
                    .arg(placeIn(child, parent).y())
                    .arg(child->width())
                    .arg(child->height());
        }
    }
    return {};
}

} // namespace

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
        QTreeView *findings = test::child<LogView>(w)->diagnosticsView();
        QTRY_VERIFY(findings->model()->rowCount() >= 3);
        const int rowHeight = findings->sizeHintForRow(0);
        QVERIFY(rowHeight > 0);
        QTRY_VERIFY2(findings->viewport()->height() >= 3 * rowHeight,
                     qPrintable(QStringLiteral("%1 px for rows of %2 px")
                                    .arg(findings->viewport()->height())
                                    .arg(rowHeight)));
        // The filter bar's controls are shown whole, inside the Log.
        const QRect log = test::child<LogView>(w)->rect();
        for (QWidget *child : test::child<LogView>(w)->filterBar()->findChildren<QWidget *>()) {
            if (!child->isVisible() ||
                child->parentWidget() != test::child<LogView>(w)->filterBar())
                continue;
            const QRect at(child->mapTo(test::child<LogView>(w), QPoint()), child->size());
            QVERIFY2(log.contains(at),
                     qPrintable(child->objectName() + u' ' + child->metaObject()->className()));
            QVERIFY2(child->width() >= child->minimumSizeHint().width(),
                     qPrintable(child->metaObject()->className()));
        }
    }

    void theHeaderAndTreesAreWholeAt1024x700()
    {
        MainWindow w;
        smallWindow(w);
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(test::dataDir(QStringLiteral("compose_system/ws")));
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTRY_VERIFY_WITH_TIMEOUT(!test::child<DiagramPanel>(w)->currentComposite().isEmpty() &&
                                     !test::child<DiagramPanel>(w)->isLayingOut(),
                                 60000);
        QCoreApplication::processEvents();

        // The main toolbar and the diagram's toolbars: every command shown.
        QString problem = toolBarProblem(&w, Qt::FindDirectChildrenOnly);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        DiagramPanel *diagram = test::child<DiagramPanel>(w);
        QVERIFY(diagram->overviewAction()->isVisible());
        problem = toolBarProblem(diagram);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
        QVERIFY(diagram->searchField()->width() >=
                diagram->searchField()->minimumSizeHint().width());

        // The diagram's header with a path too long for it: never drawn over each other or
        // past the header; the note goes first, then the crumbs between the root and the
        // composite shown, then the middle of the names; the name shown stays readable.
        DiagramBreadcrumbBar *crumbs = diagram->breadcrumbBar();
        QList<DiagramBreadcrumbBar::Crumb> path;
        for (int i = 0; i < 3; ++i)
            path.append({QStringLiteral("lf%1").arg(i),
                         QStringLiteral("unique_multi_tb3_simulation_%1").arg(i), QString()});
        crumbs->setPath(path, QStringLiteral("as included by unique_multi_tb3_simulation"));
        QCoreApplication::processEvents();
        QVERIFY(crumbs->sizeHint().width() > crumbs->width()); // it does not fit whole
        QVERIFY(diagram->rect().contains(placeIn(crumbs, diagram)));
        int right = 0;
        for (QWidget *child : crumbs->findChildren<QWidget *>()) {
            if (!child->isVisible())
                continue;
            const QRect at = placeIn(child, crumbs);
            QVERIFY2(crumbs->rect().contains(at), qPrintable(child->objectName()));
            QVERIFY2(at.left() >= right,
                     qPrintable(child->objectName() + QStringLiteral(" overlaps")));
            right = at.right() + 1;
            if (auto *button = qobject_cast<QToolButton *>(child))
                QVERIFY2(button->width() >= button->sizeHint().width(), qPrintable(button->text()));
        }
        const auto *note = crumbs->findChild<QLabel *>(QStringLiteral("crumbNote"));
        QVERIFY(note && !note->isVisible());
        QVERIFY(!crumbs->button(QStringLiteral("lf1"))->isVisible()); // the middle one went
        const QToolButton *shown = crumbs->button(QStringLiteral("lf2"));
        QVERIFY2(shown->isVisible() && shown->text().size() >= 12, qPrintable(shown->text()));

        // The root picker's entry, cut in the narrow header, is whole in its tooltip.
        auto *picker = diagram->findChild<DiagramRootPicker *>();
        QVERIFY(picker && picker->currentIndex() >= 0);
        QVERIFY2(picker->toolTip().startsWith(picker->currentText()),
                 qPrintable(picker->toolTip()));

        // The inspector's hint is whole in its short dock.
        const auto *hint = w.findChild<QLabel *>(QStringLiteral("inspectorHint"));
        QVERIFY(hint && hint->isVisible());
        QVERIFY2(hint->heightForWidth(hint->width()) <= hint->height(),
                 qPrintable(QStringLiteral("%1 px needed, %2 px given")
                                .arg(hint->heightForWidth(hint->width()))
                                .arg(hint->height())));

        // The two trees: their filters whole, and a screenful of rows.
        for (FilteredTreePanel *panel :
             {static_cast<FilteredTreePanel *>(test::child<AtomicNodePanel>(w)),
              static_cast<FilteredTreePanel *>(test::child<LaunchTreePanel>(w))}) {
            QLineEdit *filter = panel->filterEdit();
            QVERIFY(w.rect().contains(placeIn(filter, &w)));
            QVERIFY(filter->width() >= filter->minimumSizeHint().width());
            QTreeView *tree = panel->treeView();
            QVERIFY(w.rect().contains(placeIn(tree, &w)));
            const int row = tree->sizeHintForRow(0);
            QVERIFY(row > 0);
            QVERIFY2(tree->viewport()->height() >= 12 * row,
                     qPrintable(QStringLiteral("%1 px for rows of %2 px")
                                    .arg(tree->viewport()->height())
                                    .arg(row)));
        }
        test::saveScreenshot(w, QStringLiteral("window-1024x700.png"));
    }
};

QTEST_MAIN(TestSmallWindow)
#include "tst_smallwindow.moc"
