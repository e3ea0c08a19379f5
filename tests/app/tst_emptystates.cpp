// What the window's empty panels say: before a run, after a run that found
// no package, no node class or no launch file, and after a run stopped before any result.
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "pipeline/recovery.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/launchtreepanel.h"

#include <QLabel>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;
using rosarch::test::saveScreenshot;

class TestEmptyStates : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void emptyPanelsSayWhatTheRunFound()
    {
        // A folder without a package.xml says so in every panel, and the
        // diagram does not ask for a stage 3 that has run; a package without nodes or launch
        // files says that instead.
        QTemporaryDir dir;
        test::writeFile(dir.path() + QStringLiteral("/scripts/tool.py"), "print('hello')\n");
        MainWindow w;
        w.resize(1500, 900);
        w.show();
        QVERIFY(test::child<AtomicNodePanel>(w)->placeholderLabel()->text().contains(
            QStringLiteral("Open")));
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(dir.path());
        QVERIFY(finished.wait(60000));
        QVERIFY(test::child<AtomicNodePanel>(w)->placeholderLabel()->isVisible());
        QCOMPARE(test::child<AtomicNodePanel>(w)->placeholderLabel()->text(),
                 QStringLiteral("No ROS 2 package in this folder.\n\nrosarch finds packages by "
                                "their package.xml. Open the folder that holds them: a "
                                "workspace, or its src folder."));
        QCOMPARE(test::child<LaunchTreePanel>(w)->placeholderLabel()->text(),
                 QStringLiteral("No ROS 2 package in this folder, so no launch files either."));
        QCOMPARE(test::child<DiagramPanel>(w)->message(),
                 QStringLiteral("No ROS 2 package in this folder: there is nothing to compose."));
        saveScreenshot(w, QStringLiteral("empty_states_no_package.png"));

        test::writeFile(dir.path() + QStringLiteral("/src/tools/package.xml"),
                        "<package format=\"3\"><name>tools</name><export><build_type>"
                        "ament_python</build_type></export></package>\n");
        QSignalSpy again(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(dir.path());
        QVERIFY(again.wait(60000));
        QVERIFY(!test::child<AtomicNodePanel>(w)
                     ->placeholderLabel()
                     ->isVisible()); // the package, with 0 nodes
        QVERIFY(test::child<LaunchTreePanel>(w)->placeholderLabel()->text().startsWith(
            QStringLiteral("No launch files found in this workspace.")));
        QVERIFY(test::child<DiagramPanel>(w)->message().startsWith(
            QStringLiteral("No launch files, so nothing to compose")));
        saveScreenshot(w, QStringLiteral("empty_states.png"));
    }

    void aRunStoppedBeforeAResultSaysSo()
    {
        // A first run cancelled (or failed) before any result: no panel claims the workspace
        // has no packages or launch files; each says the run stopped. A finished run replaces it.
        QTemporaryDir dir;
        MainWindow w;
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(dir.path());
        QVERIFY(finished.wait(60000));
        Q_EMIT test::child<StageRunner>(w)->stageCanceled(StageRunner::Job::Recovery);
        const QString stopped =
            QStringLiteral("The run stopped before it had a result, so nothing is known yet.\n\n"
                           "Run it again with Stages → Run All.");
        QCOMPARE(test::child<AtomicNodePanel>(w)->placeholderLabel()->text(), stopped);
        QCOMPARE(test::child<LaunchTreePanel>(w)->placeholderLabel()->text(), stopped);
        QCOMPARE(test::child<DiagramPanel>(w)->message(), stopped);
        Q_EMIT test::child<StageRunner>(w)->stageFinished(Recovery());
        QVERIFY(test::child<AtomicNodePanel>(w)->placeholderLabel()->text().startsWith(
            QStringLiteral("No ROS 2 package in this folder.")));
    }
};

QTEST_MAIN(TestEmptyStates)
#include "tst_emptystates.moc"
