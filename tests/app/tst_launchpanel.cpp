#include "app/appsettings.h"
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "support/guifixture.h"
#include "support/screenshot.h"
#include "support/testsupport.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/launchargumentsdialog.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/nodefilterproxymodel.h"
#include "widgets/sourceview.h"

#include <Qsci/qscilexer.h>
#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolBar>
#include <QTreeView>
#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::gui;
using rosarch::test::saveScreenshot;

namespace {

QStringList childNames(const QAbstractItemModel *model, const QModelIndex &parent)
{
    QStringList names;
    for (int r = 0; r < model->rowCount(parent); ++r)
        names << model->index(r, 0, parent).data().toString();
    return names;
}

QString lexerLanguage(MainWindow &w)
{
    QsciLexer *lexer = test::child<SourceView>(w)->editor()->lexer();
    return lexer ? QString::fromLatin1(lexer->language()) : QString();
}

bool markedLine(MainWindow &w, int line)
{
    return test::child<SourceView>(w)->editor()->markersAtLine(line - 1) &
           (1u << test::child<SourceView>(w)->evidenceMarker());
}

/// A window on gui_ws whose stages are stubs: stage 1+2 give the hand-built model, stage 2
/// alone records the options it ran with.
struct StubbedWindow
{
    MainWindow w;
    QList<LaunchOptions> fullRuns;
    QList<LaunchOptions> launchRuns;

    StubbedWindow()
    {
        test::child<StageRunner>(w)->setStageFunction(
            [this](const QString &, const LaunchOptions &options, const StageControl &) {
                fullRuns << options;
                return handBuiltRecovery();
            });
        test::child<StageRunner>(w)->setLaunchFunction(
            [this](const QString &, const AtomicNodeList &nodes, const LaunchOptions &options,
                   const StageControl &) {
                launchRuns << options;
                LaunchDependencies d = handBuiltLaunch();
                d.nodes[0].nodeName = QStringLiteral("talker_%1").arg(nodes.nodes.size());
                return d;
            });
    }
};

} // namespace

class TestLaunchPanel : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(QFileInfo(fixture()).isDir());
    }

    void init()
    {
        QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();
    }

    void launchTreeSitsBetweenNodesAndSource()
    {
        MainWindow w;
        w.resize(1500, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QDockWidget *nodes = w.findChild<QDockWidget *>(QStringLiteral("atomicNodesDock"));
        QDockWidget *launch = w.findChild<QDockWidget *>(QStringLiteral("launchTreeDock"));
        QDockWidget *source = w.findChild<QDockWidget *>(QStringLiteral("sourceDock"));
        QVERIFY(nodes && launch && source);
        QCOMPARE(launch->windowTitle(), QStringLiteral("Launch tree"));
        QVERIFY(launch->isVisible());
        QVERIFY(nodes->geometry().right() < launch->geometry().left());
        QVERIFY(launch->geometry().right() < source->geometry().left());
        // before a run the panel says what to do instead of showing an empty tree
        QVERIFY(test::child<LaunchTreePanel>(w)->placeholderLabel()->isVisible());
        QVERIFY(test::child<LaunchTreePanel>(w)->placeholderLabel()->text().contains(
            QStringLiteral("Open")));
        // reachable from the View menu, the Stages menu and the toolbar
        QAction *toggle = launch->toggleViewAction();
        toggle->trigger();
        QVERIFY(!launch->isVisible());
        toggle->trigger();
        QVERIFY(launch->isVisible());
        QAction *arguments = test::child<QAction>(w, QStringLiteral("launchArgumentsAction"));
        QToolBar *toolBar = w.findChild<QToolBar *>(QStringLiteral("mainToolBar"));
        QVERIFY(toolBar->actions().contains(arguments));
        QVERIFY(toolBar->actions().contains(
            test::child<QAction>(w, QStringLiteral("runLaunchAction"))));
        QMenu *stages = nullptr;
        for (QMenu *m : w.findChildren<QMenu *>())
            if (m->title() == QStringLiteral("&Stages"))
                stages = m;
        QVERIFY(stages && stages->actions().contains(arguments));
        QCOMPARE(arguments->text(), QStringLiteral("Launch &Arguments…"));
    }

    void realRunShowsTheFixtureLaunchTree()
    {
        MainWindow w;
        w.resize(1500, 900);
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(test::dataDir(QStringLiteral("gui_ws")));
        QVERIFY(finished.wait(60000));
        LaunchTreeModel *model = test::child<LaunchTreeModel>(w);
        QCOMPARE(model->rowCount(), 1);
        const QModelIndex root = model->index(0, 0);
        QCOMPARE(root.data().toString(), QStringLiteral("demo.launch.py"));
        QCOMPARE(childNames(model, root),
                 (QStringList{QStringLiteral("talker"), QStringLiteral("/robot1"),
                              QStringLiteral("echo_talker")}));
        const QModelIndex robot1 = model->index(1, 0, root);
        QCOMPARE(childNames(model, robot1), QStringList{QStringLiteral("listener.launch.xml")});
        const QModelIndex listenerFile = model->index(0, 0, robot1);
        QCOMPARE(childNames(model, listenerFile),
                 (QStringList{QStringLiteral("listener"), QStringLiteral("extra.launch.yaml"),
                              QStringLiteral("talker.launch.py")}));
        const QModelIndex listener = model->index(0, 0, listenerFile);
        QCOMPARE(listener.siblingAtColumn(LaunchTreeModel::NamespaceColumn).data().toString(),
                 QStringLiteral("/robot1"));
        QCOMPARE(listener.siblingAtColumn(LaunchTreeModel::ClassColumn).data().toString(),
                 QStringLiteral("Listener"));
        QVERIFY(!model->isActive(model->index(2, 0, root))); // echo_talker: use_echo is false
        QVERIFY(model->launchFile(model->index(2, 0, listenerFile))->external);
        const QString counts = test::child<QLabel>(w, QStringLiteral("countsLabel"))->text();
        QVERIFY2(counts.contains(QStringLiteral("3 launch files · 4 instances · 0 unresolved")),
                 qPrintable(counts));
        QVERIFY(!test::child<LaunchTreePanel>(w)->placeholderLabel()->isVisible());
        QVERIFY(test::child<LaunchTreePanel>(w)->treeView()->isVisible());
        // stage 2's note about the external include is in the log
        bool external = false;
        for (int r = 0; r < test::child<LogView>(w)->diagnosticsView()->model()->rowCount(); ++r)
            external |= test::child<LogView>(w)
                            ->diagnosticsView()
                            ->model()
                            ->index(r, DiagnosticModel::MessageColumn)
                            .data()
                            .toString()
                            .contains(QStringLiteral("demo_nodes_cpp"));
        QVERIFY(external);

        // selecting the node instance shows its launch line and selects its class
        test::child<LaunchTreePanel>(w)->selectSourceIndex(listener);
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListenerLaunch);
        QCOMPARE(test::child<SourceView>(w)->highlighted().line, 3);
        QVERIFY(markedLine(w, 3));
        QCOMPARE(lexerLanguage(w), QStringLiteral("XML"));
        const QModelIndex cls = test::child<AtomicNodePanel>(w)->currentSourceIndex();
        QCOMPARE(
            cls.data(AtomicNodeModel::NodeIdRole).toString(),
            test::child<Document>(w)->launchDependencies().node(QStringLiteral("n2"))->classId);
        QCOMPARE(cls.data().toString(), QStringLiteral("Listener"));
        saveScreenshot(w, QStringLiteral("launchtree_fixture.png"));

        // File → Export writes stage 2's artifact too
        QTemporaryDir out;
        QVERIFY(w.exportArtifactsTo(out.path()));
        const QByteArray json =
            test::readFile(QDir(out.path()).filePath(QStringLiteral("launch_dependencies.json")));
        QVERIFY2(json.contains("listener.launch.xml") && json.contains("second_listener"),
                 json.left(300).constData());
    }

    void selectingInstancesTracesToClassAndSource()
    {
        MainWindow w;
        w.resize(1500, 900);
        w.show();
        test::child<Document>(w)->setRecovery(handBuiltRecovery());
        LaunchTreeModel *model = test::child<LaunchTreeModel>(w);

        // a node of the Python launch file: Python lexer, the Node(...) call marked
        test::child<LaunchTreePanel>(w)->selectSourceIndex(model->nodeIndex(QStringLiteral("n1")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kDemoLaunch);
        QCOMPARE(test::child<SourceView>(w)->highlighted(), (Evidence{kDemoLaunch, 18, 9, 20, 41}));
        QCOMPARE(lexerLanguage(w), QStringLiteral("Python"));
        QVERIFY(test::child<SourceView>(w)->editor()->text(17).contains(
            QStringLiteral("Node(package='py_talker'")));
        QCOMPARE(test::child<AtomicNodePanel>(w)->currentSourceIndex(),
                 test::child<AtomicNodeModel>(w)->nodeIndex(QStringLiteral("arc_2")));

        // an include row shows the include line in the including file
        test::child<LaunchTreePanel>(w)->selectSourceIndex(
            model->launchFileIndex(QStringLiteral("lf3")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListenerLaunch);
        QCOMPARE(test::child<SourceView>(w)->highlighted().line, 6);
        QVERIFY(test::child<SourceView>(w)->editor()->text(5).contains(
            QStringLiteral("extra.launch.yaml")));
        // the YAML file's node: YAML lexer
        test::child<LaunchTreePanel>(w)->selectSourceIndex(model->nodeIndex(QStringLiteral("n3")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kExtraLaunch);
        QCOMPARE(lexerLanguage(w), QStringLiteral("YAML"));
        QVERIFY(markedLine(w, 2));

        // Go to Class: the atomic tree takes over the source view
        QAction *goToClass = test::child<LaunchTreePanel>(w)->goToClassAction();
        QVERIFY(goToClass->isEnabled());
        goToClass->trigger();
        QCOMPARE(test::child<AtomicNodePanel>(w)->currentSourceIndex(),
                 test::child<AtomicNodeModel>(w)->nodeIndex(QStringLiteral("arc_1")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kListener);
        QCOMPARE(test::child<SourceView>(w)->highlighted().line, 11);
        // not for rows without a class
        test::child<LaunchTreePanel>(w)->selectSourceIndex(
            model->launchFileIndex(QStringLiteral("lf4")));
        QVERIFY(!goToClass->isEnabled());

        // double-click on a node instance goes to its class too
        const QModelIndex talkerRow = test::child<LaunchTreePanel>(w)->proxyModel()->mapFromSource(
            model->nodeIndex(QStringLiteral("n4")));
        QTreeView *tree = test::child<LaunchTreePanel>(w)->treeView();
        tree->scrollTo(talkerRow);
        const QPoint center = tree->visualRect(talkerRow).center();
        QSignalSpy requested(test::child<LaunchTreePanel>(w), &LaunchTreePanel::classRequested);
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, center);  // the press a
        QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {}, center); // double-click needs
        QCOMPARE(requested.count(), 1);
        QCOMPARE(test::child<AtomicNodePanel>(w)->currentSourceIndex(),
                 test::child<AtomicNodeModel>(w)->nodeIndex(QStringLiteral("arc_2")));
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kTalker);
    }

    void sourceCursorSelectsTheLaunchItem()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        test::child<Document>(w)->setRecovery(handBuiltRecovery());
        LaunchTreeModel *model = test::child<LaunchTreeModel>(w);
        test::child<LaunchTreePanel>(w)->selectSourceIndex(model->nodeIndex(QStringLiteral("n1")));
        const Evidence shown = test::child<SourceView>(w)->highlighted();
        QsciScintilla *editor = test::child<SourceView>(w)->editor();
        QTest::qWait(50); // QScintilla reports cursor moves on its next UI update
        QCOMPARE(test::child<LaunchTreePanel>(w)->currentSourceIndex(),
                 model->nodeIndex(QStringLiteral("n1")));

        editor->setCursorPosition(28, 12); // line 29: inside the echo talker's Node(...)
        QTRY_COMPARE(test::child<LaunchTreePanel>(w)->currentSourceIndex(),
                     model->nodeIndex(QStringLiteral("n4")));
        QCOMPARE(test::child<AtomicNodePanel>(w)->currentSourceIndex(),
                 test::child<AtomicNodeModel>(w)->nodeIndex(QStringLiteral("arc_2")));
        // following the cursor moves neither the source nor its highlight
        QCOMPARE(test::child<SourceView>(w)->highlighted(), shown);
        QCOMPARE(test::child<SourceView>(w)->currentFile(), kDemoLaunch);
        int line = -1, index = -1;
        editor->getCursorPosition(&line, &index);
        QCOMPARE(line, 28);

        editor->setCursorPosition(23, 4); // line 24: the include of listener.launch.xml
        QTRY_COMPARE(test::child<LaunchTreePanel>(w)->currentSourceIndex(),
                     model->launchFileIndex(QStringLiteral("lf2")));
        editor->setCursorPosition(9, 0); // line 10: no action, the file itself
        QTRY_COMPARE(test::child<LaunchTreePanel>(w)->currentSourceIndex(),
                     model->launchFileIndex(QStringLiteral("lf1")));

        // with a filter hiding the item, following the cursor clears the filter
        test::child<LaunchTreePanel>(w)->filterEdit()->setText(QStringLiteral("second_listener"));
        editor->setCursorPosition(17, 10);
        QTRY_COMPARE(test::child<LaunchTreePanel>(w)->currentSourceIndex(),
                     model->nodeIndex(QStringLiteral("n1")));
        QVERIFY(test::child<LaunchTreePanel>(w)->filterEdit()->text().isEmpty());
    }

    void filterAndFindInTheLaunchTree()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        test::child<Document>(w)->setRecovery(handBuiltRecovery());
        QTreeView *tree = test::child<LaunchTreePanel>(w)->treeView();
        tree->setFocus();
        QTest::keyClick(&w, Qt::Key_F, Qt::ControlModifier); // Find in the tree with focus
        QLineEdit *filter = test::child<LaunchTreePanel>(w)->filterEdit();
        QVERIFY(filter->hasFocus());
        QTest::keyClicks(filter, QStringLiteral("/robot1/extra"));
        QAbstractItemModel *proxy = tree->model();
        QCOMPARE(proxy->rowCount(), 1);
        QModelIndex row = proxy->index(0, 0);
        QStringList path;
        while (proxy->rowCount(row) > 0) {
            row = proxy->index(0, 0, row);
            path << row.data().toString();
        }
        QCOMPARE(path,
                 (QStringList{QStringLiteral("/robot1"), QStringLiteral("listener.launch.xml"),
                              QStringLiteral("extra.launch.yaml"), QStringLiteral("/robot1/extra"),
                              QStringLiteral("second_listener")}));
        QTest::keyClick(filter, Qt::Key_Escape);
        QVERIFY(filter->text().isEmpty());
        QCOMPARE(proxy->rowCount(proxy->index(0, 0)), 3);
    }

    void expandedRowsAreKeptAcrossANewResult()
    {
        MainWindow w;
        w.show();
        test::child<Document>(w)->setRecovery(handBuiltRecovery());
        QTreeView *tree = test::child<LaunchTreePanel>(w)->treeView();
        QAbstractItemModel *proxy = tree->model();
        // a small tree opens fully, but for the nodes' parameters
        const QModelIndex root = proxy->index(0, 0);
        QVERIFY(tree->isExpanded(root));
        QModelIndex included;
        for (int r = 0; r < proxy->rowCount(root) && !included.isValid(); ++r)
            if (proxy->hasChildren(proxy->index(r, 0, root)))
                included = proxy->index(r, 0, root);
        QVERIFY(included.isValid());
        QVERIFY(tree->isExpanded(included));
        const QString includedName = included.data().toString();
        // the person closes one row; a new result (a re-run) keeps it closed, the rest open
        tree->collapse(included);
        Recovery again = handBuiltRecovery();
        again.launch.nodes[0].nodeName = QStringLiteral("renamed_by_the_rerun");
        test::child<Document>(w)->setRecovery(again);
        const QModelIndex rootAfter = proxy->index(0, 0);
        QVERIFY(tree->isExpanded(rootAfter));
        bool found = false;
        for (int r = 0; r < proxy->rowCount(rootAfter); ++r) {
            const QModelIndex i = proxy->index(r, 0, rootAfter);
            if (i.data().toString() == includedName) {
                found = true;
                QVERIFY(!tree->isExpanded(i));
            }
        }
        QVERIFY(found);
        // Expand All opens it again
        tree->expandAll();
        test::child<LaunchTreePanel>(w)->filterEdit()->setText(QStringLiteral("no such row"));
        QCOMPARE(proxy->rowCount(), 0);
        test::child<LaunchTreePanel>(w)->filterEdit()->clear();
        QVERIFY(tree->isExpanded(proxy->index(0, 0)));
    }

    void argumentsDialogShowsAndReturnsOptions()
    {
        LaunchArgumentsDialog dialog;
        dialog.setLaunchDependencies(handBuiltLaunch(), QString());
        LaunchOptions given;
        given.arguments = {{QStringLiteral("use_echo"), QStringLiteral("true")}};
        dialog.setOptions(given);
        QComboBox *root = dialog.rootCombo();
        QCOMPARE(root->count(), 4);
        QCOMPARE(root->itemText(0), QStringLiteral("All top-level launch files"));
        QCOMPARE(root->currentIndex(), 0);
        QTableWidget *table = dialog.table();
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(0, LaunchArgumentsDialog::NameColumn)->text(),
                 QStringLiteral("robot"));
        QCOMPARE(table->item(0, LaunchArgumentsDialog::DefaultColumn)->text(),
                 QStringLiteral("robot1"));
        QCOMPARE(table->item(0, LaunchArgumentsDialog::DescriptionColumn)->text(),
                 QStringLiteral("Namespace of the robot"));
        QCOMPARE(table->item(0, LaunchArgumentsDialog::FileColumn)->text(),
                 QStringLiteral("demo.launch.py"));
        QCOMPARE(table->item(0, LaunchArgumentsDialog::FileColumn)->toolTip(),
                 kDemoLaunch + QStringLiteral(":14"));
        QCOMPARE(table->item(1, LaunchArgumentsDialog::ValueColumn)->text(),
                 QStringLiteral("true"));
        QVERIFY(
            !(table->item(0, LaunchArgumentsDialog::DefaultColumn)->flags() & Qt::ItemIsEditable));
        QVERIFY(table->item(0, LaunchArgumentsDialog::ValueColumn)->flags() & Qt::ItemIsEditable);
        saveScreenshot(dialog, QStringLiteral("launch_arguments.png"));

        table->item(0, LaunchArgumentsDialog::ValueColumn)->setText(QStringLiteral("r2"));
        root->setCurrentIndex(root->findData(kDemoLaunch));
        QCOMPARE(table->rowCount(), 2); // demo.launch.py declares both
        QCOMPARE(table->item(0, LaunchArgumentsDialog::ValueColumn)->text(), QStringLiteral("r2"));
        LaunchOptions expected;
        expected.rootFile = kDemoLaunch;
        expected.arguments = {{QStringLiteral("robot"), QStringLiteral("r2")},
                              {QStringLiteral("use_echo"), QStringLiteral("true")}};
        QCOMPARE(dialog.options(), expected);

        // a root stage 2 has not analysed: its arguments are unknown; typed values stay
        root->setCurrentIndex(root->findData(kListenerLaunch));
        QVERIFY(dialog.hintLabel()->isVisibleTo(&dialog));
        QVERIFY(dialog.hintLabel()->text().contains(QStringLiteral("listener.launch.xml")));
        QCOMPARE(table->rowCount(), 2); // the values set, as arguments it does not declare
        QVERIFY(table->item(0, LaunchArgumentsDialog::NameColumn)->flags() & Qt::ItemIsEditable);
        QCOMPARE(dialog.options().arguments, expected.arguments);
        QCOMPARE(dialog.options().rootFile, kListenerLaunch);

        // Use Defaults clears every value
        for (QPushButton *b : dialog.findChildren<QPushButton *>())
            if (b->text() == QStringLiteral("Use &Defaults"))
                b->click();
        QVERIFY(dialog.options().arguments.isEmpty());
    }

    void argumentsDialogRerunsStageTwoAndOptionsPersist()
    {
        LaunchOptions chosen;
        chosen.rootFile = kDemoLaunch;
        chosen.arguments = {{QStringLiteral("robot"), QStringLiteral("r2")}};
        {
            StubbedWindow s;
            MainWindow &w = s.w;
            w.show();
            QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
            QSignalSpy launchFinished(test::child<StageRunner>(w),
                                      &StageRunner::launchStageFinished);
            w.openWorkspace(fixture());
            QVERIFY(finished.wait(10000));
            QCOMPARE(s.fullRuns.size(), 1);
            QCOMPARE(s.fullRuns.first(), LaunchOptions()); // nothing chosen yet
            test::child<LaunchTreePanel>(w)->selectSourceIndex(
                test::child<LaunchTreeModel>(w)->nodeIndex(QStringLiteral("n3")));

            test::child<QAction>(w, QStringLiteral("launchArgumentsAction"))->trigger();
            auto *dialog = w.findChild<LaunchArgumentsDialog *>();
            QVERIFY(dialog && dialog->isVisible());
            QCOMPARE(dialog->table()->rowCount(), 2);
            dialog->table()
                ->item(0, LaunchArgumentsDialog::ValueColumn)
                ->setText(QStringLiteral("r2"));
            dialog->rootCombo()->setCurrentIndex(dialog->rootCombo()->findData(kDemoLaunch));
            dialog->accept();

            QCOMPARE(test::child<Document>(w)->session()->launchOptions(), chosen);
            QCOMPARE(AppSettings().launchOptions(fixture()), chosen);
            QVERIFY(launchFinished.wait(10000));
            QCOMPARE(s.launchRuns, QList<LaunchOptions>{chosen});
            QCOMPARE(s.fullRuns.size(), 1); // stage 2 alone, against the current classes
            QCOMPARE(test::child<Document>(w)->launchDependencies().nodes.first().nodeName,
                     QStringLiteral("talker_2"));
            QCOMPARE(test::child<Document>(w)->atomicNodes().nodes.size(), 2);
            // the selection survives the re-run
            QCOMPARE(test::child<LaunchTreePanel>(w)->currentSourceIndex(),
                     test::child<LaunchTreeModel>(w)->nodeIndex(QStringLiteral("n3")));

            // re-running keeps them: stage 2 alone (F6) and both stages (F5)
            test::child<QAction>(w, QStringLiteral("runLaunchAction"))->trigger();
            QVERIFY(launchFinished.wait(10000));
            QCOMPARE(s.launchRuns.last(), chosen);
            w.runAllStages();
            QVERIFY(finished.wait(10000));
            QCOMPARE(s.fullRuns.last(), chosen);
            w.close();
        }
        // another window on the same workspace starts from them
        StubbedWindow again;
        QSignalSpy finished(test::child<StageRunner>(again.w), &StageRunner::stageFinished);
        again.w.openWorkspace(fixture());
        QCOMPARE(test::child<Document>(again.w)->session()->launchOptions(), chosen);
        QVERIFY(finished.wait(10000));
        QCOMPARE(again.fullRuns.first(), chosen);
        // and restores the launch item selected when the last one closed
        QCOMPARE(test::child<LaunchTreePanel>(again.w)->currentSourceIndex(),
                 test::child<LaunchTreeModel>(again.w)->nodeIndex(QStringLiteral("n3")));
    }

    void launchOptionsAreKeptPerWorkspace()
    {
        QTemporaryDir other;
        LaunchOptions a;
        a.rootFile = kDemoLaunch;
        a.arguments = {{QStringLiteral("robot"), QStringLiteral("alpha")},
                       {QStringLiteral("path"), QStringLiteral("/opt/x y")}};
        LaunchOptions b;
        b.arguments = {{QStringLiteral("use_sim_time"), QStringLiteral("true")}};
        AppSettings().setLaunchOptions(fixture(), a);
        AppSettings().setLaunchOptions(other.path(), b);
        QCOMPARE(AppSettings().launchOptions(fixture()), a);
        QCOMPARE(AppSettings().launchOptions(other.path()), b);
        AppSettings().setLaunchOptions(other.path(), {});
        QCOMPARE(AppSettings().launchOptions(other.path()), LaunchOptions());
        QCOMPARE(AppSettings().launchOptions(fixture()), a);
    }

    void exampleWorkspaceLaunchTree()
    {
        MainWindow w;
        w.resize(1600, 950);
        w.show();
        QSignalSpy finished(test::child<StageRunner>(w), &StageRunner::stageFinished);
        w.openWorkspace(QStringLiteral(ROSARCH_EXAMPLE_WORKSPACE));
        QVERIFY(finished.wait(60000));
        const LaunchDependencies &launch = test::child<Document>(w)->launchDependencies();
        QVERIFY(launch.launchFiles.size() >= 4);
        LaunchTreeModel *model = test::child<LaunchTreeModel>(w);
        QModelIndex robot;
        for (int r = 0; r < model->rowCount(); ++r)
            if (model->index(r, 0).data().toString() == QLatin1String("robot.launch.py"))
                robot = model->index(r, 0);
        QVERIFY(robot.isValid());
        // every node instance has a row, shows its line and, with a class, selects it
        int withClass = 0;
        for (const NodeInstance &n : launch.nodes) {
            const QModelIndex row = model->nodeIndex(n.id);
            QVERIFY2(row.isValid(), qPrintable(n.id));
            test::child<LaunchTreePanel>(w)->selectSourceIndex(row);
            QCOMPARE(test::child<SourceView>(w)->currentFile(), n.evidence.file);
            QVERIFY(markedLine(w, n.evidence.line));
            if (!n.classId.isEmpty()) {
                ++withClass;
                QCOMPARE(test::child<AtomicNodePanel>(w)->currentSourceIndex(),
                         test::child<AtomicNodeModel>(w)->nodeIndex(n.classId));
            }
        }
        QVERIFY(withClass >= 6);
        // a composable node sits under its container
        bool composableUnderContainer = false;
        for (const NodeInstance &n : launch.nodes)
            if (n.nodeKind == QLatin1String("composable") && launch.node(n.container))
                composableUnderContainer |=
                    model->nodeIndex(n.id).parent() == model->nodeIndex(n.container);
        QVERIFY(composableUnderContainer);
        QVERIFY(test::child<QLabel>(w, QStringLiteral("countsLabel"))
                    ->text()
                    .contains(QStringLiteral("%1 launch files").arg(launch.launchFiles.size())));
        QTest::qWait(50);
        const auto it = std::find_if(launch.nodes.cbegin(), launch.nodes.cend(),
                                     [](const NodeInstance &n) { return !n.classId.isEmpty(); });
        test::child<LaunchTreePanel>(w)->selectSourceIndex(model->nodeIndex(it->id));
        saveScreenshot(w, QStringLiteral("launchtree_example.png"));
    }
};

QTEST_MAIN(TestLaunchPanel)
#include "tst_launchpanel.moc"
