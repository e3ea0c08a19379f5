// The root the composed diagram starts on, in the main window: RootChoice's pick on a
// workspace opened for the first time, a root chosen in the diagram's header remembered for
// that workspace, and the remembered one shown first when the workspace is opened again.
#include "app/appsettings.h"
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "support/testsupport.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramrootpicker.h"

#include <QDir>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace rosarch;

namespace {

/// gui_ws (demo.launch.py including listener, which includes extra and an external talker) and
/// two roots of one node each.
void makeWorkspace(const QString &root)
{
    test::copyTree(test::dataDir(QStringLiteral("gui_ws")), root);
    for (const char *name : {"alpha", "beta"})
        test::writeFile(
            QDir(root).filePath(QStringLiteral("src/py_talker/launch/%1.launch.xml").arg(name)),
            QByteArrayLiteral("<launch>\n  <node pkg=\"py_talker\" exec=\"talker\" "
                              "name=\"") +
                name + QByteArrayLiteral("\"/>\n</launch>\n"));
}

/// The stem of the root the window's diagram shows.
QString shownStem(MainWindow &w)
{
    const Composite *c = test::child<DiagramPanel>(w)->architecture().composite(
        test::child<DiagramPanel>(w)->breadcrumbIds().value(0));
    return c ? c->stem : QString();
}

bool openAndWait(MainWindow &w, const QString &root)
{
    QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
    w.openWorkspace(root);
    while (finished.isEmpty() || test::child<StageRunner>(w)->isRunning())
        if (!finished.wait(60000))
            return false;
    DiagramPanel *panel = test::child<DiagramPanel>(w);
    QSignalSpy laidOut(panel, &DiagramPanel::layoutFinished);
    return !panel->isLayingOut() || laidOut.wait(30000);
}

} // namespace

class TestDiagramRoots : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
             QStringLiteral("/projects"))
            .removeRecursively();
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
    }

    void chosenRootIsRemembered()
    {
        QTemporaryDir dir;
        const QString root = dir.filePath(QStringLiteral("ws"));
        makeWorkspace(root);
        {
            MainWindow w;
            w.resize(1500, 900);
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QVERIFY(openAndWait(w, root));
            // No name says which: demo includes the most, so it comes first.
            QCOMPARE(shownStem(w), QStringLiteral("demo"));
            DiagramRootPicker *picker = test::child<DiagramPanel>(w)->rootPicker();
            QCOMPARE(picker->count(), 3);
            QCOMPARE(picker->currentText(), QStringLiteral("demo — 3 includes"));
            const int beta = picker->findText(QStringLiteral("beta — 0 includes"));
            QVERIFY(beta >= 0);
            QSignalSpy laidOut(test::child<DiagramPanel>(w), &DiagramPanel::layoutFinished);
            picker->setCurrentIndex(beta);
            Q_EMIT picker->activated(beta);
            QVERIFY(!laidOut.isEmpty() || laidOut.wait(30000));
            QCOMPARE(shownStem(w), QStringLiteral("beta"));
            QCOMPARE(AppSettings().diagramRoot(root),
                     QStringLiteral("src/py_talker/launch/beta.launch.xml"));
        }
        // Opened again: beta, as the person left it.
        MainWindow again;
        again.resize(1500, 900);
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QVERIFY(openAndWait(again, root));
        QCOMPARE(shownStem(again), QStringLiteral("beta"));
        QCOMPARE(test::child<DiagramPanel>(again)->rootPicker()->currentText(),
                 QStringLiteral("beta — 0 includes"));
    }
};

QTEST_MAIN(TestDiagramRoots)
#include "tst_diagramroots.moc"
