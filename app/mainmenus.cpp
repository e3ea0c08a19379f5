#include "app/mainmenus.h"
#include "app/aboutdialog.h"
#include "app/appsettings.h"
#include "app/comparecontroller.h"
#include "app/correctioncontroller.h"
#include "app/diagramcontroller.h"
#include "app/diagramfocus.h"
#include "app/navigationcontroller.h"
#include "app/paneldocks.h"
#include "app/projectcontroller.h"
#include "app/rendercontroller.h"
#include "app/stagerunner.h"
#include "app/suggestioncontroller.h"
#include "app/workspacewatcher.h"
#include "document/document.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/icons.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QToolBar>
#include <QUndoStack>

namespace rosarch {

MainMenus::MainMenus(QMainWindow *window, const Parts &parts)
    : QObject(window), m_window(window), m_parts(parts)
{
    createActions();
    createFileMenu();
    createEditMenu();
    createToolBar();
    createViewMenu();
    QMenu *go = m_window->menuBar()->addMenu(tr("&Go"));
    go->addAction(m_parts.navigation->backAction());
    go->addAction(m_parts.navigation->forwardAction());
    createModelMenu();
    createStagesMenu();
    QMenu *help = m_window->menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
    help->addAction(m_aboutQtAction);
}

QAction *MainMenus::addAction(const QString &text, const QString &name)
{
    auto *action = new QAction(text, this);
    action->setObjectName(name);
    return action;
}

void MainMenus::createActions()
{
    PanelDocks *docks = m_parts.docks;
    m_openAction = addAction(tr("&Open Workspace…"), QStringLiteral("openWorkspaceAction"));
    m_openAction->setIcon(Icons::open());
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a ROS 2 workspace folder and recover its architecture"));
    connect(m_openAction, &QAction::triggered, this, &MainMenus::openWorkspaceRequested);

    m_exportAction = addAction(tr("&Export Artifacts…"), QStringLiteral("exportArtifactsAction"));
    m_exportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    m_exportAction->setStatusTip(
        tr("Write the JSON artifacts and the PlantUML diagrams: one per node class (ACD) and "
           "one per launch file (CCD)"));
    connect(m_exportAction, &QAction::triggered, this, &MainMenus::exportArtifactsRequested);
    m_exportNodlAction = addAction(tr("Export &NoDL…"), QStringLiteral("exportNodlAction"));
    m_exportNodlAction->setStatusTip(
        tr("Write one NoDL description per node class: its parameters, topics, services and "
           "actions, as ros-tooling/nodl reads them"));
    connect(m_exportNodlAction, &QAction::triggered, this, &MainMenus::exportNodlRequested);

    m_quitAction = addAction(tr("&Quit"), QStringLiteral("quitAction"));
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, m_window, &QWidget::close);

    m_undoAction = m_parts.document->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setObjectName(QStringLiteral("undoAction"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_redoAction = m_parts.document->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setObjectName(QStringLiteral("redoAction"));
    m_redoAction->setShortcut(QKeySequence::Redo);

    m_findAction = addAction(tr("&Find…"), QStringLiteral("findAction"));
    m_findAction->setShortcut(QKeySequence::Find);
    m_findAction->setStatusTip(tr("Filter the node tree, or the launch tree when it has the "
                                  "focus, by name"));
    connect(m_findAction, &QAction::triggered, this, [docks] {
        // Find filters the tree a person works in; the atomic nodes by default.
        LaunchTreePanel *launch = docks->launchPanel();
        if (launch->isAncestorOf(QApplication::focusWidget()) && launch->isVisible()) {
            launch->focusFilter();
            return;
        }
        docks->bringForward(PanelDocks::Dock::Nodes);
        docks->nodePanel()->focusFilter();
    });

    m_nextDiagnosticAction = addAction(tr("&Next Finding"), QStringLiteral("nextFindingAction"));
    m_nextDiagnosticAction->setShortcut(QKeySequence(Qt::Key_F8));
    connect(m_nextDiagnosticAction, &QAction::triggered, this, [docks] {
        docks->dock(PanelDocks::Dock::Log)->show();
        docks->logView()->selectNextDiagnostic();
    });
    m_previousDiagnosticAction =
        addAction(tr("&Previous Finding"), QStringLiteral("previousFindingAction"));
    m_previousDiagnosticAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F8));
    connect(m_previousDiagnosticAction, &QAction::triggered, this, [docks] {
        docks->dock(PanelDocks::Dock::Log)->show();
        docks->logView()->selectPreviousDiagnostic();
    });

    m_runAction = addAction(tr("&Run All Stages"), QStringLiteral("runAllAction"));
    m_runAction->setIcon(Icons::run());
    m_runAction->setIconText(tr("Run all"));
    m_runAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_runAction->setToolTip(tr("Recover the atomic nodes, the launch tree and the composed "
                               "architecture of the workspace (F5)"));
    m_runAction->setStatusTip(tr("Stage 1 finds node classes, their ports and executables; "
                                 "stage 2 reads the launch files; stage 3 composes them"));
    connect(m_runAction, &QAction::triggered, this, &MainMenus::runAllRequested);

    m_runLaunchAction =
        addAction(tr("Run Stage &2: Launch Files"), QStringLiteral("runLaunchAction"));
    m_runLaunchAction->setIcon(Icons::runLaunch());
    m_runLaunchAction->setIconText(tr("Stage 2"));
    m_runLaunchAction->setShortcut(QKeySequence(Qt::Key_F6));
    m_runLaunchAction->setToolTip(tr("Read the launch files again against the current atomic "
                                     "nodes, with the chosen launch arguments (F6)"));
    m_runLaunchAction->setStatusTip(tr("Re-run stage 2 only: launch files, includes, namespaces "
                                       "and node instances"));
    connect(m_runLaunchAction, &QAction::triggered, this, &MainMenus::runLaunchRequested);

    m_launchArgumentsAction =
        addAction(tr("Launch &Arguments…"), QStringLiteral("launchArgumentsAction"));
    m_launchArgumentsAction->setIcon(Icons::launchArguments());
    m_launchArgumentsAction->setIconText(tr("Arguments"));
    m_launchArgumentsAction->setShortcut(QKeySequence(tr("Ctrl+Shift+A")));
    m_launchArgumentsAction->setToolTip(
        tr("Choose the root launch file and the launch argument values for stage 2"));
    connect(m_launchArgumentsAction, &QAction::triggered, this,
            &MainMenus::launchArgumentsRequested);

    m_cancelAction = addAction(tr("&Cancel Stage"), QStringLiteral("cancelStageAction"));
    m_cancelAction->setIcon(Icons::stop());
    m_cancelAction->setIconText(tr("Cancel"));
    m_cancelAction->setShortcut(QKeySequence(Qt::Key_Escape));
    m_cancelAction->setToolTip(tr("Stop the running stage and keep the previous result (Esc)"));
    connect(m_cancelAction, &QAction::triggered, m_parts.runner, &StageRunner::cancel);

    m_suggestAction = addAction(tr("&Suggest (Stage 4)"), QStringLiteral("suggestAction"));
    m_suggestAction->setIconText(tr("LLM"));
    m_suggestAction->setShortcut(QKeySequence(Qt::Key_F7));
    m_suggestAction->setToolTip(tr("Propose node descriptions and subsystem groupings for review "
                                   "(F7); asks the LLM when one is configured"));
    SuggestionController *suggestions = m_parts.suggestions;
    connect(m_suggestAction, &QAction::triggered, this, [docks, suggestions] {
        docks->bringForward(PanelDocks::Dock::Suggestions);
        suggestions->run();
    });
    connect(suggestions, &SuggestionController::runningChanged, m_suggestAction,
            [this](bool running) { m_suggestAction->setEnabled(!running); });

    m_watchAction =
        addAction(tr("&Watch Workspace for Changes"), QStringLiteral("watchWorkspaceAction"));
    m_watchAction->setCheckable(true);
    m_watchAction->setChecked(m_parts.watcher->isEnabled());
    m_watchAction->setToolTip(tr("Analyse again when a source, build, launch or parameter file "
                                 "of the workspace changes on disk"));
    WorkspaceWatcher *watcher = m_parts.watcher;
    connect(m_watchAction, &QAction::toggled, this, [watcher](bool on) {
        AppSettings().setWatchWorkspace(on);
        watcher->setEnabled(on);
    });
    m_resetLayoutAction = addAction(tr("&Reset Layout"), QStringLiteral("resetLayoutAction"));
    connect(m_resetLayoutAction, &QAction::triggered, docks, &PanelDocks::resetLayout);

    m_aboutAction = addAction(tr("&About rosarch"), QStringLiteral("aboutAction"));
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, [this] {
        AboutDialog dialog(m_window);
        dialog.exec();
    });
    m_aboutQtAction = addAction(tr("About &Qt"), QStringLiteral("aboutQtAction"));
    m_aboutQtAction->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQtAction, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainMenus::createFileMenu()
{
    QMenu *file = m_window->menuBar()->addMenu(tr("&File"));
    file->addAction(m_parts.projects->newAction());
    file->addAction(m_openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainMenus::updateRecentMenu);
    file->addAction(m_parts.projects->openAction());
    file->addMenu(m_parts.projects->recentMenu());
    file->addSeparator();
    file->addAction(m_parts.projects->saveAction());
    file->addAction(m_parts.projects->saveAsAction());
    file->addSeparator();
    file->addAction(m_exportAction);
    file->addAction(m_exportNodlAction);
    QAction *exportSite = file->addAction(tr("Export Architecture &Site…"));
    exportSite->setObjectName(QStringLiteral("exportSiteAction"));
    exportSite->setStatusTip(tr("Write the accepted model as a static HTML site a newcomer reads "
                                "in a browser: systems with their diagrams, nodes, topics, "
                                "launch files, findings and a search"));
    connect(exportSite, &QAction::triggered, this, &MainMenus::exportSiteRequested);
    file->addAction(m_parts.diagrams->exportSvgAction());
    file->addAction(m_parts.diagrams->exportPngAction());
    file->addSeparator();
    file->addAction(m_parts.render->renderAction());
    file->addAction(m_parts.render->jarAction());
    file->addSeparator();
    file->addAction(m_parts.diagrams->compareAction());
    file->addAction(m_parts.diagrams->clearComparisonAction());
    file->addAction(m_parts.compare->compareFolderAction());
    file->addAction(m_parts.compare->compareRevisionAction());
    file->addSeparator();
    file->addAction(m_quitAction);
}

void MainMenus::createEditMenu()
{
    QMenu *edit = m_window->menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_findAction);
    edit->addSeparator();
    edit->addAction(m_nextDiagnosticAction);
    edit->addAction(m_previousDiagnosticAction);
}

void MainMenus::createToolBar()
{
    QToolBar *bar = m_window->addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->setMovable(false);
    bar->addAction(m_openAction);
    bar->addSeparator();
    bar->addAction(m_parts.navigation->backAction());
    bar->addAction(m_parts.navigation->forwardAction());
    bar->addSeparator();
    bar->addAction(m_runAction);
    bar->addAction(m_runLaunchAction);
    bar->addAction(m_launchArgumentsAction);
    bar->addAction(m_suggestAction);
    bar->addAction(m_cancelAction);
    bar->toggleViewAction()->setText(tr("&Toolbar"));
}

void MainMenus::createViewMenu()
{
    QMenu *view = m_window->menuBar()->addMenu(tr("&View"));
    view->addActions(m_parts.docks->toggleViewActions());
    for (QToolBar *bar : m_window->findChildren<QToolBar *>(QStringLiteral("mainToolBar")))
        view->addAction(bar->toggleViewAction());
    view->addSeparator();
    view->addAction(m_parts.docks->diagramFocus()->action());
    view->addSeparator();
    view->addAction(m_watchAction);
    view->addAction(m_resetLayoutAction);
}

void MainMenus::createModelMenu()
{
    QMenu *model = m_window->menuBar()->addMenu(tr("&Model"));
    CorrectionController *corrections = m_parts.corrections;
    PanelDocks *docks = m_parts.docks;
    // The element's own actions: what the inspector shows, rebuilt whenever the menu opens.
    connect(model, &QMenu::aboutToShow, this, [model, corrections, docks] {
        model->clear();
        const QList<QAction *> actions = corrections->actionsFor(corrections->current(), model);
        if (actions.isEmpty()) {
            QAction *none = model->addAction(tr("Select an element to correct it"));
            none->setEnabled(false);
        }
        model->addActions(actions);
        model->addSeparator();
        QAction *show = model->addAction(tr("Show &Corrections"));
        connect(show, &QAction::triggered, docks,
                [docks] { docks->bringForward(PanelDocks::Dock::Corrections); });
        QAction *inspect = model->addAction(tr("Show &Inspector"));
        connect(inspect, &QAction::triggered, docks,
                [docks] { docks->bringForward(PanelDocks::Dock::Inspector); });
    });
    QAction *placeholder = model->addAction(tr("Select an element to correct it"));
    placeholder->setEnabled(false);
}

void MainMenus::createStagesMenu()
{
    QMenu *stages = m_window->menuBar()->addMenu(tr("&Stages"));
    stages->addAction(m_runAction);
    stages->addAction(m_runLaunchAction);
    stages->addAction(m_suggestAction);
    stages->addSeparator();
    stages->addAction(m_launchArgumentsAction);
    stages->addSeparator();
    stages->addAction(m_cancelAction);
}

void MainMenus::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = AppSettings().recentWorkspaces();
    if (recent.isEmpty()) {
        m_recentMenu->addAction(tr("No recent workspaces"))->setEnabled(false);
        return;
    }
    for (int i = 0; i < recent.size(); ++i) {
        const QString &path = recent[i];
        const QString label = tr("&%1 %2 — %3")
                                  .arg(i + 1 < 10 ? QString::number(i + 1) : QStringLiteral("1&0"))
                                  .arg(QFileInfo(path).fileName(), QDir::toNativeSeparators(path));
        QAction *action = m_recentMenu->addAction(label);
        action->setData(path);
        connect(action, &QAction::triggered, this, [this, path] { emit workspaceRequested(path); });
    }
    m_recentMenu->addSeparator();
    connect(m_recentMenu->addAction(tr("&Clear Menu")), &QAction::triggered, this,
            [] { AppSettings().clearRecentWorkspaces(); });
}

void MainMenus::enableForResult(bool hasWorkspace, qsizetype diagnostics)
{
    m_exportAction->setEnabled(hasWorkspace);
    m_nextDiagnosticAction->setEnabled(diagnostics > 0);
    m_previousDiagnosticAction->setEnabled(diagnostics > 0);
}

} // namespace rosarch
