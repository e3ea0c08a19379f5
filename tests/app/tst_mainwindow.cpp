#include "app/appsettings.h"
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/logview.h"
#include "widgets/nodefilterproxymodel.h"
#include "widgets/sourceview.h"

#include <Qsci/qscilexer.h>
#include <Qsci/qsciscintilla.h>

#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QSettings>
#include <QSignalSpy>
#include <QSortFilterProxyModel>
#include <QTemporaryDir>
#include <QThread>
#include <QToolButton>
#include <QTreeView>
#include <QUndoStack>
#include <QtTest>

using namespace rosarch;

using namespace rosarch::test::gui;
using rosarch::test::saveScreenshot;

namespace {

AtomicNodeList handBuiltFixtureModel()
{
    return handBuiltNodes();
}

QModelIndex treeCurrent(MainWindow &w)
{
    return test::child<AtomicNodePanel>(w)->currentSourceIndex();
}

} // namespace

class TestMainWindow : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
        QVERIFY(QFileInfo(fixture()).isDir());
    }

    void init()
    {
        // every test starts without projects: an edit a test left unsaved would otherwise be
        // offered for recovery (a dialog) when the next one opens the workspace
        QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
                 .filePath(QStringLiteral("projects")))
            .removeRecursively();
    }

    void stageOneOnFixture()
    {
        MainWindow w;
        w.resize(1400, 900);
        w.show();
        QSignalSpy started(test::child<StageRunner>(w), &StageRunner::stageStarted);
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(test::dataDir(QStringLiteral("gui_ws")));
        QCOMPARE(started.count(), 1);
        QCOMPARE(w.workspace(), fixture());
        QLabel *counts = test::child<QLabel>(w, QStringLiteral("countsLabel"));
        // Before a first result, no counts: they would all read 0.
        QVERIFY(!counts->isVisible());
        QVERIFY(finished.wait(60000));
        QTRY_VERIFY(counts->isVisible());
        QCOMPARE(test::child<Document>(w)->workspaceRoot(), fixture());
        QCOMPARE(AppSettings().recentWorkspaces().value(0), fixture());
        QCOMPARE(AppSettings().lastWorkspace(), fixture());

        const AtomicNodeList &list = test::child<Document>(w)->atomicNodes();
        QStringList classes;
        for (const AtomicNode &n : list.nodes)
            classes << n.className;
        QCOMPARE(classes, (QStringList{QStringLiteral("Listener"), QStringLiteral("Talker")}));
        AtomicNodeModel *model = test::child<AtomicNodeModel>(w);
        const QModelIndex py = model->packageIndex(QStringLiteral("py_talker"));
        const QModelIndex cpp = model->packageIndex(QStringLiteral("cpp_listener"));
        QVERIFY(py.isValid() && cpp.isValid());
        QCOMPARE(model->rowCount(py), 1);
        QCOMPARE(model->rowCount(cpp), 1);
        const QModelIndex talker = model->index(0, 0, py);
        QCOMPARE(talker.data().toString(), QStringLiteral("Talker"));
        QStringList talkerPorts;
        for (int r = 0; r < model->rowCount(talker); ++r)
            talkerPorts << model->index(r, 0, talker).data().toString();
        QVERIFY2(talkerPorts.contains(QStringLiteral("chatter")),
                 qPrintable(talkerPorts.join(',')));
        QVERIFY2(talkerPorts.contains(QStringLiteral("echo")), qPrintable(talkerPorts.join(',')));
        const QModelIndex listener = model->index(0, 0, cpp);
        QStringList listenerTypes;
        for (int r = 0; r < model->rowCount(listener); ++r)
            listenerTypes
                << model->index(r, AtomicNodeModel::TypeColumn, listener).data().toString();
        QVERIFY2(listenerTypes.contains(QStringLiteral("std_srvs/srv/Trigger")),
                 qPrintable(listenerTypes.join(',')));
        QVERIFY2(counts->text().contains(QStringLiteral("2 nodes")), qPrintable(counts->text()));
        // the tree shows them (expanded, through the filter proxy)
        QTreeView *tree = test::child<AtomicNodePanel>(w)->treeView();
        QCOMPARE(tree->model()->rowCount(), 2);
        QVERIFY(tree->isExpanded(tree->model()->index(0, 0)));
        saveScreenshot(w, QStringLiteral("mainwindow_stage1.png"));
    }

    void selectingPortShowsEvidence()
    {
        MainWindow w;
        w.resize(1400, 900);
        w.show();
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        const QModelIndex pub = test::child<AtomicNodeModel>(w)->portIndex(QStringLiteral("arc_2"),
                                                                           QStringLiteral("p1"));
        QVERIFY(pub.isValid());
        test::child<AtomicNodePanel>(w)->selectSourceIndex(pub);

        SourceView *source = test::child<SourceView>(w);
        QCOMPARE(source->currentFile(), kTalker);
        QCOMPARE(source->highlighted().line, 11);
        QsciScintilla *editor = source->editor();
        QVERIFY(
            editor->text(10).contains(QStringLiteral("create_publisher(String, 'chatter', 10)")));
        QVERIFY(editor->markersAtLine(10) & (1u << source->evidenceMarker()));
        QVERIFY(!(editor->markersAtLine(11) & (1u << source->evidenceMarker())));
        // the indicator covers the call, not the assignment before it
        const long lineStart = editor->SendScintilla(QsciScintilla::SCI_POSITIONFROMLINE, 10);
        const auto indicatorAt = [&](long pos) {
            return editor->SendScintilla(QsciScintilla::SCI_INDICATORVALUEAT,
                                         source->evidenceIndicator(), pos);
        };
        QVERIFY(indicatorAt(lineStart + 25) != 0); // column 26: "self.create_publisher"
        QVERIFY(indicatorAt(lineStart + 10) == 0); // "publisher =" is not evidence
        int line = -1, index = -1;
        editor->getCursorPosition(&line, &index);
        QCOMPARE(line, 10);
        QVERIFY(editor->isReadOnly());
        QVERIFY(editor->lexer() != nullptr);
        QCOMPARE(QString::fromLatin1(editor->lexer()->language()), QStringLiteral("Python"));

        // a C++ port switches file and lexer
        test::child<AtomicNodePanel>(w)->selectSourceIndex(
            test::child<AtomicNodeModel>(w)->portIndex(QStringLiteral("arc_1"),
                                                       QStringLiteral("ps1")));
        QCOMPARE(source->currentFile(), kListener);
        QCOMPARE(QString::fromLatin1(editor->lexer()->language()), QStringLiteral("C++"));
        QVERIFY(editor->text(18).contains(QStringLiteral("create_service")));
        QVERIFY(editor->markersAtLine(18) & (1u << source->evidenceMarker()));
        saveScreenshot(w, QStringLiteral("mainwindow_traceability.png"));
    }

    void sourceCursorSelectsInnermostElement()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        AtomicNodeModel *model = test::child<AtomicNodeModel>(w);
        const QModelIndex pub = model->portIndex(QStringLiteral("arc_2"), QStringLiteral("p1"));
        test::child<AtomicNodePanel>(w)->selectSourceIndex(pub);
        const Evidence shown = test::child<SourceView>(w)->highlighted();
        QsciScintilla *editor = test::child<SourceView>(w)->editor();
        QTest::qWait(50); // QScintilla reports cursor moves on its next UI update
        QCOMPARE(treeCurrent(w), pub);

        editor->setCursorPosition(11, 8); // line 12: the subscription
        QTRY_COMPARE(treeCurrent(w),
                     model->portIndex(QStringLiteral("arc_2"), QStringLiteral("s1")));
        // following the source does not move the source (no feedback loop)
        QCOMPARE(test::child<SourceView>(w)->highlighted(), shown);
        int line = -1, index = -1;
        editor->getCursorPosition(&line, &index);
        QCOMPARE(line, 11);

        editor->setCursorPosition(15, 0); // line 16: inside Talker, outside any port
        QTRY_COMPARE(treeCurrent(w), model->nodeIndex(QStringLiteral("arc_2")));
        editor->setCursorPosition(24, 0); // line 25: main(), outside every element
        QTest::qWait(50);
        QCOMPARE(treeCurrent(w), model->nodeIndex(QStringLiteral("arc_2")));

        // with a filter hiding the element, selecting from the source clears the filter
        test::child<AtomicNodePanel>(w)->filterEdit()->setText(QStringLiteral("Listener"));
        editor->setCursorPosition(10, 0);
        QTRY_COMPARE(treeCurrent(w), pub);
        QVERIFY(test::child<AtomicNodePanel>(w)->filterEdit()->text().isEmpty());
    }

    void diagnosticsNavigateToSource()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        QCOMPARE(test::child<LogView>(w)->diagnosticsView()->model()->rowCount(), 1);
        test::child<LogView>(w)->selectNextDiagnostic();
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListener);
        QCOMPARE(test::child<SourceView>(w)->highlighted().line, 19);
        // showing a diagnostic's line does not echo into the tree (line 19 holds port ps1)
        QTest::qWait(50);
        QVERIFY(!treeCurrent(w).isValid());
        // moving away and pressing F8 again shows it again (wraps onto the same row)
        test::child<AtomicNodePanel>(w)->selectSourceIndex(
            test::child<AtomicNodeModel>(w)->portIndex(QStringLiteral("arc_2"),
                                                       QStringLiteral("p1")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kTalker);
        QTest::keyClick(&w, Qt::Key_F8);
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListener);
        test::child<AtomicNodePanel>(w)->selectSourceIndex(
            test::child<AtomicNodeModel>(w)->portIndex(QStringLiteral("arc_2"),
                                                       QStringLiteral("p1")));
        QTest::keyClick(&w, Qt::Key_F8, Qt::ShiftModifier);
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListener);
        QCOMPARE(test::child<SourceView>(w)->highlighted().line, 19);
    }

    void aFindingIsAcceptedAsAnExpectedExternal()
    {
        // check_roots reports the planner's /map, which (say) a map server outside the
        // workspace publishes.
        QTemporaryDir ws;
        test::copyTree(test::dataDir(QStringLiteral("check_roots/ws")), ws.path());
        MainWindow w;
        w.resize(1400, 900);
        w.show();
        w.openWorkspace(ws.path());
        const auto scanFinding = [&w]() -> QModelIndex {
            QAbstractItemModel *m = test::child<LogView>(w)->diagnosticsView()->model();
            for (int r = 0; r < m->rowCount(); ++r)
                if (m->index(r, DiagnosticModel::MessageColumn)
                        .data()
                        .toString()
                        .contains(QStringLiteral("subscribes to /map,")))
                    return m->index(r, 0);
            return {};
        };
        QTRY_VERIFY_WITH_TIMEOUT(scanFinding().isValid(), 60000);
        QAction *accept = test::child<LogView>(w)->acceptExternalAction();
        test::child<LogView>(w)->diagnosticsView()->setCurrentIndex(scanFinding());
        QVERIFY(accept->isEnabled());
        accept->trigger();
        QCOMPARE(test::child<Document>(w)->session()->launchOptions().externals.size(),
                 qsizetype(1));
        const ExpectedExternal &e =
            test::child<Document>(w)->session()->launchOptions().externals.front();
        QCOMPARE(e.name, QStringLiteral("/map"));
        QVERIFY(!e.output);
        // The checks run again, without it; the project keeps the declaration.
        QTRY_VERIFY_WITH_TIMEOUT(
            !scanFinding().isValid() &&
                !test::child<Document>(w)->architecture().diagnostics.isEmpty(),
            60000);
        QCOMPARE(test::child<Document>(w)->session()->project().launch.externals.size(),
                 qsizetype(1));
        QStringList left;
        for (const Diagnostic &d : test::child<Document>(w)->architecture().diagnostics)
            left << d.external;
        left.sort();
        QCOMPARE(left, (QStringList{QStringLiteral("input /odom_raws"),
                                    QStringLiteral("input /robot1/map")}));
    }

    void exampleWorkspace()
    {
        MainWindow w;
        w.resize(1500, 950);
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(QStringLiteral(ROSARCH_EXAMPLE_WORKSPACE));
        QVERIFY(finished.wait(60000));
        const AtomicNodeList &list = test::child<Document>(w)->atomicNodes();
        QVERIFY(list.nodes.size() >= 4);
        // every node and port with evidence can be shown, at its line
        for (const AtomicNode &n : list.nodes) {
            for (const Port &p : n.ports) {
                test::child<AtomicNodePanel>(w)->selectSourceIndex(
                    test::child<AtomicNodeModel>(w)->portIndex(n.id, p.id));
                QCOMPARE(test::child<SourceView>(w)->currentFile(), p.evidence.file);
                QVERIFY(test::child<SourceView>(w)->editor()->markersAtLine(p.evidence.line - 1) &
                        (1u << test::child<SourceView>(w)->evidenceMarker()));
            }
        }
        const AtomicNode &last = list.nodes.last();
        if (!last.ports.isEmpty())
            test::child<AtomicNodePanel>(w)->selectSourceIndex(
                test::child<AtomicNodeModel>(w)->portIndex(last.id, last.ports.last().id));
        saveScreenshot(w, QStringLiteral("mainwindow_example.png"));
    }

    void findFiltersTheTree()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        QTest::keyClick(&w, Qt::Key_F, Qt::ControlModifier);
        QLineEdit *filter = test::child<AtomicNodePanel>(w)->filterEdit();
        QVERIFY(filter->hasFocus());
        QTest::keyClicks(filter, QStringLiteral("Trigger"));
        QAbstractItemModel *proxy = test::child<AtomicNodePanel>(w)->treeView()->model();
        QCOMPARE(proxy->rowCount(), 1);
        const QModelIndex node = proxy->index(0, 0, proxy->index(0, 0));
        QCOMPARE(proxy->rowCount(node), 1);
        QCOMPARE(proxy->index(0, 0, node).data().toString(), QStringLiteral("reset"));
        QTest::keyClick(filter, Qt::Key_Escape);
        QVERIFY(filter->text().isEmpty());
        QCOMPARE(proxy->rowCount(), 2);
    }

    void undoRedoFromTheEditMenu()
    {
        MainWindow w;
        w.show();
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        QAction *undo = nullptr;
        QAction *redo = nullptr;
        for (QAction *a : w.findChildren<QAction *>()) {
            if (a->shortcut() == QKeySequence(QKeySequence::Undo))
                undo = a;
            if (a->shortcut() == QKeySequence(QKeySequence::Redo))
                redo = a;
        }
        QVERIFY(undo && redo);
        QVERIFY(!undo->isEnabled());
        const QModelIndex description = test::child<AtomicNodeModel>(w)->nodeIndex(
            QStringLiteral("arc_1"), AtomicNodeModel::DescriptionColumn);
        QVERIFY(test::child<AtomicNodeModel>(w)->setData(description, QStringLiteral("Listens.")));
        QVERIFY(undo->isEnabled());
        undo->trigger();
        QCOMPARE(test::child<Document>(w)->atomicNodes().nodes.first().description, QString());
        QVERIFY(redo->isEnabled());
        redo->trigger();
        QCOMPARE(test::child<Document>(w)->atomicNodes().nodes.first().description,
                 QStringLiteral("Listens."));
    }

    void f2EditsTheDescription()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        test::child<AtomicNodePanel>(w)->selectSourceIndex(
            test::child<AtomicNodeModel>(w)->nodeIndex(QStringLiteral("arc_2")));
        QTreeView *tree = test::child<AtomicNodePanel>(w)->treeView();
        tree->setFocus();
        QTest::keyClick(tree, Qt::Key_F2);
        QLineEdit *editor = tree->viewport()->findChild<QLineEdit *>();
        QVERIFY(editor);
        QTest::keyClicks(editor, QStringLiteral("Greets the world."));
        QTest::keyClick(editor, Qt::Key_Return); // the delegate commits on the event loop
        QTRY_COMPARE(
            test::child<Document>(w)->atomicNodes().node(QStringLiteral("arc_2"))->description,
            QStringLiteral("Greets the world."));
        QCOMPARE(test::child<Document>(w)->undoStack()->count(), 1);
    }

    void dropFolderOpensWorkspace()
    {
        MainWindow w;
        w.show();
        QSignalSpy started(test::child<StageRunner>(w), &StageRunner::stageStarted);
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        QMimeData data;
        data.setUrls({QUrl::fromLocalFile(test::dataDir(QStringLiteral("gui_ws")))});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &data, Qt::LeftButton,
                              Qt::NoModifier);
        QCoreApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &data, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&w, &drop);
        QCOMPARE(started.count(), 1);
        QCOMPARE(w.workspace(), fixture());
        QVERIFY(finished.wait(60000));

        QMimeData file;
        file.setUrls(
            {QUrl::fromLocalFile(test::dataDir(QStringLiteral("gui_ws/src/py_talker/setup.py")))});
        QDragEnterEvent fileEnter(QPoint(10, 10), Qt::CopyAction, &file, Qt::LeftButton,
                                  Qt::NoModifier);
        fileEnter.ignore();
        QCoreApplication::sendEvent(&w, &fileEnter);
        QVERIFY(!fileEnter.isAccepted()); // a file is not a workspace
    }

    void missingFolderExplainsAndIsNotRemembered()
    {
        MainWindow w;
        w.show();
        QSignalSpy started(test::child<StageRunner>(w), &StageRunner::stageStarted);
        const QString missing = QDir::temp().filePath(QStringLiteral("rosarch-no-such-ws-4711"));
        w.openWorkspace(missing);
        QCOMPARE(started.count(), 0);
        QVERIFY(!AppSettings().recentWorkspaces().contains(missing));
        QMessageBox *box = w.findChild<QMessageBox *>();
        QVERIFY(box);
        QVERIFY(box->isVisible());
        QVERIFY(box->text().contains(QStringLiteral("rosarch-no-such-ws-4711")));
        QVERIFY(box->text().contains(QStringLiteral("Open Workspace")));
        box->close();
    }

    void openRecentMenuReopens()
    {
        AppSettings().clearRecentWorkspaces();
        AppSettings().addRecentWorkspace(fixture());
        MainWindow w;
        QMenu *recent = nullptr;
        for (QMenu *m : w.findChildren<QMenu *>())
            if (m->title() == QStringLiteral("Open &Recent"))
                recent = m;
        QVERIFY(recent);
        Q_EMIT recent->aboutToShow();
        QAction *entry = nullptr;
        for (QAction *a : recent->actions())
            if (a->data().toString() == fixture())
                entry = a;
        QVERIFY(entry);
        QVERIFY(entry->text().contains(QStringLiteral("gui_ws")));
        QSignalSpy started(test::child<StageRunner>(w), &StageRunner::stageStarted);
        entry->trigger();
        QCOMPARE(started.count(), 1);
        QCOMPARE(w.workspace(), fixture());

        AppSettings().clearRecentWorkspaces();
        Q_EMIT recent->aboutToShow();
        QCOMPARE(recent->actions().size(), 1);
        QVERIFY(!recent->actions().first()->isEnabled()); // "No recent workspaces"
    }

    void recentListDropsMissingFolders()
    {
        QTemporaryDir gone;
        AppSettings settings;
        settings.clearRecentWorkspaces();
        settings.addRecentWorkspace(gone.path());
        for (int i = 0; i < 12; ++i)
            settings.addRecentWorkspace(fixture()); // no duplicates
        QCOMPARE(settings.recentWorkspaces(),
                 (QStringList{fixture(), QFileInfo(gone.path()).canonicalFilePath()}));
        gone.remove();
        QCOMPARE(settings.recentWorkspaces(), QStringList{fixture()});
        settings.clearRecentWorkspaces();
        QVERIFY(settings.recentWorkspaces().isEmpty());
    }

    void exportWritesArtifacts()
    {
        MainWindow w;
        test::child<Document>(w)->setAtomicNodes(handBuiltFixtureModel());
        QTemporaryDir out;
        QVERIFY(w.exportArtifactsTo(out.path()));
        const QByteArray json =
            test::readFile(QDir(out.path()).filePath(QStringLiteral("atomic_nodes.json")));
        QVERIFY2(json.contains("list_packages"), json.left(200).constData());
        QVERIFY(json.contains("Talker"));

        QFile blocker(QDir(out.path()).filePath(QStringLiteral("not_a_folder")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        QVERIFY(!w.exportArtifactsTo(blocker.fileName()));
        QMessageBox *box = w.findChild<QMessageBox *>();
        QVERIFY(box);
        QVERIFY(box->text().contains(QStringLiteral("not_a_folder")));
        box->close();
    }

    void windowStaysResponsiveWhileRunning()
    {
        MainWindow w;
        w.show();
        test::child<StageRunner>(w)->setStageFunction(
            [](const QString &root, const LaunchOptions &, const StageControl &control) {
                Recovery result;
                result.nodes.workspaceRoot = root;
                for (int i = 0; i < 400 && !control.isCanceled(); ++i) {
                    control.report(i, 400, QStringLiteral("Reading file %1").arg(i));
                    QThread::msleep(5);
                }
                result.nodes.canceled = control.isCanceled();
                return result;
            });
        QSignalSpy progressed(test::child<StageRunner>(w), &StageRunner::stageProgressed);
        QSignalSpy canceled(test::child<StageRunner>(w), &StageRunner::stageCanceled);
        w.openWorkspace(test::dataDir(QStringLiteral("gui_ws")));
        QVERIFY(progressed.wait(5000));
        QProgressBar *bar = w.findChild<QProgressBar *>();
        QVERIFY(bar && bar->isVisible());
        QCOMPARE(bar->maximum(), 400);
        saveScreenshot(w, QStringLiteral("mainwindow_running.png"));
        QTest::keyClick(&w, Qt::Key_Escape); // Stages → Cancel
        QVERIFY(canceled.wait(5000));
        QVERIFY(!bar->isVisible());
        QVERIFY(
            test::child<LogView>(w)->logEdit()->toPlainText().contains(QStringLiteral("canceled")));
    }

    void aCrashInAnalysisLeavesTheWindowAndTheModel()
    {
        // The stages run in the worker process: a crash there is a message in the log, and
        // the window, its model and the person's edits stay.
        MainWindow w;
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        QSignalSpy failed(test::child<StageRunner>(w), &StageRunner::stageFailed);
        w.openWorkspace(test::dataDir(QStringLiteral("gui_ws")));
        QVERIFY(finished.wait(60000));
        QCOMPARE(test::child<Document>(w)->atomicNodes().nodes.size(), 2);

        QTemporaryDir bin;
        StageProcess::Options dying;
        dying.helperPath = test::script(bin, QStringLiteral("dying-worker"), "kill -SEGV $$");
        test::child<StageRunner>(w)->setProcessOptions(dying);
        QTest::keyClick(&w, Qt::Key_F5); // Stages → Run all
        QVERIFY(failed.wait(30000));
        QCOMPARE(finished.count(), 1);
        QVERIFY(w.isVisible());
        QCOMPARE(test::child<Document>(w)->atomicNodes().nodes.size(), 2);
        const QString log = test::child<LogView>(w)->logEdit()->toPlainText();
        QVERIFY2(log.contains(QStringLiteral("stopped without a result; the previous result is "
                                             "kept. The analysis stopped outside the work on "
                                             "any one file")),
                 qPrintable(log));
        QVERIFY(log.contains(QStringLiteral("crashed (signal 11)")));
        saveScreenshot(w, QStringLiteral("mainwindow_worker_crashed.png"));

        // A crash while one file is analysed costs that file; the rest is shown.
        test::child<StageRunner>(w)->setProcessOptions({});
        qputenv("ROSARCH_STAGES_TEST_CRASH_IN", "talker.py");
        QTest::keyClick(&w, Qt::Key_F5);
        QVERIFY(finished.wait(60000));
        qunsetenv("ROSARCH_STAGES_TEST_CRASH_IN");
        QStringList classes;
        for (const AtomicNode &n : test::child<Document>(w)->atomicNodes().nodes)
            classes << n.className;
        QCOMPARE(classes, QStringList{QStringLiteral("Listener")});
        bool said = false;
        for (const Diagnostic &d : test::child<Document>(w)->atomicNodes().diagnostics)
            said = said || (d.code == QLatin1String("file-skipped") &&
                            d.message.contains(QLatin1String("crashed (signal ")));
        QVERIFY(said);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
