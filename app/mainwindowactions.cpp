// MainWindow's actions, menus and toolbar (the rest of the class is in mainwindow.cpp).
#include "app/aboutdialog.h"
#include "app/appsettings.h"
#include "app/changeselector.h"
#include "app/commands/siteexport.h"
#include "app/comparecontroller.h"
#include "app/diagramcontroller.h"
#include "app/diagramfocus.h"
#include "app/mainwindow.h"
#include "app/navigationcontroller.h"
#include "app/projectcontroller.h"
#include "app/rendercontroller.h"
#include "app/siteexportdialog.h"
#include "app/stagerunner.h"
#include "app/suggestioncontroller.h"
#include "app/workspacewatcher.h"
#include "artifacts/nodlwriter.h"
#include "document/document.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/icons.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMenuBar>
#include <QProgressDialog>
#include <QStatusBar>
#include <QToolBar>
#include <QUndoStack>

namespace rosarch {

void MainWindow::createActions()
{
    m_projects = new ProjectController(m_document, m_logView, this);
    m_navigation = new NavigationController(
        m_document, {m_nodePanel, m_launchPanel, m_diagramPanel, m_sourceView, m_logView}, this);
    auto *changes =
        new ChangeSelector(m_document, m_changesView, m_traceability, m_diagramPanel, this);
    connect(changes, &ChangeSelector::statusMessage, statusBar(), &QStatusBar::showMessage);

    m_openAction = new QAction(Icons::open(), tr("&Open Workspace…"), this);
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a ROS 2 workspace folder and recover its architecture"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openWorkspaceDialog);

    m_exportAction = new QAction(tr("&Export Artifacts…"), this);
    m_exportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    m_exportAction->setStatusTip(
        tr("Write the JSON artifacts and the PlantUML diagrams: one per node class (ACD) and "
           "one per launch file (CCD)"));
    connect(m_exportAction, &QAction::triggered, this, &MainWindow::exportArtifactsDialog);
    m_exportNodlAction = new QAction(tr("Export &NoDL…"), this);
    m_exportNodlAction->setStatusTip(
        tr("Write one NoDL description per node class: its parameters, topics, services and "
           "actions, as ros-tooling/nodl reads them"));
    connect(m_exportNodlAction, &QAction::triggered, this, [this] {
        const QString folder = QFileDialog::getExistingDirectory(
            this, tr("Export NoDL To"),
            workspace().isEmpty() ? QDir::homePath() : QFileInfo(workspace()).path());
        if (!folder.isEmpty())
            exportNodlTo(folder);
    });

    m_quitAction = new QAction(tr("&Quit"), this);
    m_quitAction->setShortcut(QKeySequence::Quit);
    m_quitAction->setMenuRole(QAction::QuitRole);
    connect(m_quitAction, &QAction::triggered, this, &QWidget::close);

    m_undoAction = m_document->undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_redoAction = m_document->undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setShortcut(QKeySequence::Redo);

    m_findAction = new QAction(tr("&Find…"), this);
    m_findAction->setShortcut(QKeySequence::Find);
    m_findAction->setStatusTip(tr("Filter the node tree, or the launch tree when it has the "
                                  "focus, by name"));
    connect(m_findAction, &QAction::triggered, this, [this] {
        // Find filters the tree a person works in; the atomic nodes by default.
        if (m_launchPanel->isAncestorOf(QApplication::focusWidget()) &&
            m_launchPanel->isVisible()) {
            m_launchPanel->focusFilter();
            return;
        }
        m_nodeDock->show();
        m_nodeDock->raise();
        m_nodePanel->focusFilter();
    });

    m_nextDiagnosticAction = new QAction(tr("&Next Finding"), this);
    m_nextDiagnosticAction->setShortcut(QKeySequence(Qt::Key_F8));
    connect(m_nextDiagnosticAction, &QAction::triggered, this, [this] {
        m_logDock->show();
        m_logView->selectNextDiagnostic();
    });
    m_previousDiagnosticAction = new QAction(tr("&Previous Finding"), this);
    m_previousDiagnosticAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F8));
    connect(m_previousDiagnosticAction, &QAction::triggered, this, [this] {
        m_logDock->show();
        m_logView->selectPreviousDiagnostic();
    });

    m_runAction = new QAction(Icons::run(), tr("&Run All Stages"), this);
    m_runAction->setIconText(tr("Run all"));
    m_runAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_runAction->setToolTip(tr("Recover the atomic nodes, the launch tree and the composed "
                               "architecture of the workspace (F5)"));
    m_runAction->setStatusTip(tr("Stage 1 finds node classes, their ports and executables; "
                                 "stage 2 reads the launch files; stage 3 composes them"));
    connect(m_runAction, &QAction::triggered, this, &MainWindow::runAllStages);

    m_runLaunchAction = new QAction(Icons::runLaunch(), tr("Run Stage &2: Launch Files"), this);
    m_runLaunchAction->setIconText(tr("Stage 2"));
    m_runLaunchAction->setShortcut(QKeySequence(Qt::Key_F6));
    m_runLaunchAction->setToolTip(tr("Read the launch files again against the current atomic "
                                     "nodes, with the chosen launch arguments (F6)"));
    m_runLaunchAction->setStatusTip(tr("Re-run stage 2 only: launch files, includes, namespaces "
                                       "and node instances"));
    connect(m_runLaunchAction, &QAction::triggered, this, &MainWindow::runLaunchStage);

    m_launchArgumentsAction = new QAction(Icons::launchArguments(), tr("Launch &Arguments…"), this);
    m_launchArgumentsAction->setIconText(tr("Arguments"));
    m_launchArgumentsAction->setShortcut(QKeySequence(tr("Ctrl+Shift+A")));
    m_launchArgumentsAction->setToolTip(
        tr("Choose the root launch file and the launch argument values for stage 2"));
    connect(m_launchArgumentsAction, &QAction::triggered, this,
            &MainWindow::showLaunchArgumentsDialog);

    m_cancelAction = new QAction(Icons::stop(), tr("&Cancel Stage"), this);
    m_cancelAction->setIconText(tr("Cancel"));
    m_cancelAction->setShortcut(QKeySequence(Qt::Key_Escape));
    m_cancelAction->setToolTip(tr("Stop the running stage and keep the previous result (Esc)"));
    connect(m_cancelAction, &QAction::triggered, m_runner, &StageRunner::cancel);

    m_suggestAction = new QAction(tr("&Suggest (Stage 4)"), this);
    m_suggestAction->setIconText(tr("LLM"));
    m_suggestAction->setShortcut(QKeySequence(Qt::Key_F7));
    m_suggestAction->setToolTip(tr("Propose node descriptions and subsystem groupings for review "
                                   "(F7); asks the LLM when one is configured"));
    connect(m_suggestAction, &QAction::triggered, this, [this] {
        m_suggestionDock->show();
        m_suggestionDock->raise();
        m_suggestions->run();
    });
    connect(m_suggestions, &SuggestionController::runningChanged, m_suggestAction,
            [this](bool running) { m_suggestAction->setEnabled(!running); });

    m_watchAction = new QAction(tr("&Watch Workspace for Changes"), this);
    m_watchAction->setCheckable(true);
    m_watchAction->setChecked(m_watcher->isEnabled());
    m_watchAction->setToolTip(tr("Analyse again when a source, build, launch or parameter file "
                                 "of the workspace changes on disk"));
    connect(m_watchAction, &QAction::toggled, this, [this](bool on) {
        AppSettings().setWatchWorkspace(on);
        m_watcher->setEnabled(on);
    });
    m_resetLayoutAction = new QAction(tr("&Reset Layout"), this);
    connect(m_resetLayoutAction, &QAction::triggered, this, &MainWindow::resetLayout);

    m_aboutAction = new QAction(tr("&About rosarch"), this);
    m_aboutAction->setMenuRole(QAction::AboutRole);
    connect(m_aboutAction, &QAction::triggered, this, [this] {
        AboutDialog dialog(this);
        dialog.exec();
    });
    m_aboutQtAction = new QAction(tr("About &Qt"), this);
    m_aboutQtAction->setMenuRole(QAction::AboutQtRole);
    connect(m_aboutQtAction, &QAction::triggered, qApp, &QApplication::aboutQt);
}

void MainWindow::createMenus()
{
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_projects->newAction());
    file->addAction(m_openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::updateRecentMenu);
    file->addAction(m_projects->openAction());
    file->addMenu(m_projects->recentMenu());
    file->addSeparator();
    file->addAction(m_projects->saveAction());
    file->addAction(m_projects->saveAsAction());
    file->addSeparator();
    file->addAction(m_exportAction);
    file->addAction(m_exportNodlAction);
    QAction *exportSite = file->addAction(tr("Export Architecture &Site…"));
    exportSite->setObjectName(QStringLiteral("exportSiteAction"));
    exportSite->setStatusTip(tr("Write the accepted model as a static HTML site a newcomer reads "
                                "in a browser: systems with their diagrams, nodes, topics, "
                                "launch files, findings and a search"));
    connect(exportSite, &QAction::triggered, this, [this] {
        if (workspace().isEmpty()) {
            showError(tr("Export failed"), tr("Open a workspace first: the site shows its "
                                              "architecture."));
            return;
        }
        SiteExportDialog dialog(workspace(), this);
        if (dialog.exec() != QDialog::Accepted)
            return;
        SiteOptions options = dialog.options();
        options.version = QApplication::applicationVersion();
        // The pages and their diagrams take seconds on a big workspace: a worker writes them.
        auto *job = new SiteExport(this);
        auto *progress =
            new QProgressDialog(tr("Writing the architecture site…"), tr("Cancel"), 0, 0, this);
        progress->setWindowModality(Qt::WindowModal);
        progress->setMinimumDuration(400);
        connect(job, &SiteExport::progressed, progress, [progress](int done, int total) {
            progress->setMaximum(total);
            progress->setValue(done);
        });
        connect(progress, &QProgressDialog::canceled, job, &SiteExport::cancel);
        connect(job, &SiteExport::finished, this,
                [this, job, progress](bool ok, const QString &message) {
                    progress->reset();
                    progress->deleteLater();
                    job->deleteLater();
                    m_logView->appendLog(message);
                    if (ok)
                        statusBar()->showMessage(message, 5000);
                    else
                        showError(
                            tr("Export failed"),
                            tr("The architecture site could not be written:\n%1").arg(message));
                });
        job->start(m_document->accepted(), m_document->session()->project(), options);
    });
    file->addAction(m_diagrams->exportSvgAction());
    file->addAction(m_diagrams->exportPngAction());
    file->addSeparator();
    file->addAction(m_render->renderAction());
    file->addAction(m_render->jarAction());
    file->addSeparator();
    file->addAction(m_diagrams->compareAction());
    file->addAction(m_diagrams->clearComparisonAction());
    file->addAction(m_compare->compareFolderAction());
    file->addAction(m_compare->compareRevisionAction());
    file->addSeparator();
    file->addAction(m_quitAction);

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    edit->addAction(m_findAction);
    edit->addSeparator();
    edit->addAction(m_nextDiagnosticAction);
    edit->addAction(m_previousDiagnosticAction);

    m_toolBar = addToolBar(tr("Main"));
    m_toolBar->setObjectName(QStringLiteral("mainToolBar"));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toolBar->setMovable(false);
    m_toolBar->addAction(m_openAction);
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_navigation->backAction());
    m_toolBar->addAction(m_navigation->forwardAction());
    m_toolBar->addSeparator();
    m_toolBar->addAction(m_runAction);
    m_toolBar->addAction(m_runLaunchAction);
    m_toolBar->addAction(m_launchArgumentsAction);
    m_toolBar->addAction(m_suggestAction);
    m_toolBar->addAction(m_cancelAction);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget *dock :
         {m_nodeDock, m_launchDock, m_diagramDock, m_sourceDock, m_suggestionDock, m_logDock})
        view->addAction(dock->toggleViewAction());
    view->addAction(m_changesDock->toggleViewAction());
    view->addAction(m_talkersDock->toggleViewAction());
    view->addAction(m_parameterDock->toggleViewAction());
    view->addAction(m_correctionsDock->toggleViewAction());
    view->addAction(m_inspectorDock->toggleViewAction());
    m_toolBar->toggleViewAction()->setText(tr("&Toolbar"));
    view->addAction(m_toolBar->toggleViewAction());
    view->addSeparator();
    m_diagramFocus = new DiagramFocus(this, m_diagramDock);
    view->addAction(m_diagramFocus->action());
    view->addSeparator();
    view->addAction(m_watchAction);
    view->addAction(m_resetLayoutAction);

    QMenu *go = menuBar()->addMenu(tr("&Go"));
    go->addAction(m_navigation->backAction());
    go->addAction(m_navigation->forwardAction());

    createCorrectionMenu();

    QMenu *stages = menuBar()->addMenu(tr("&Stages"));
    stages->addAction(m_runAction);
    stages->addAction(m_runLaunchAction);
    stages->addAction(m_suggestAction);
    stages->addSeparator();
    stages->addAction(m_launchArgumentsAction);
    stages->addSeparator();
    stages->addAction(m_cancelAction);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
    help->addAction(m_aboutQtAction);
}

bool MainWindow::exportNodlTo(const QString &folder)
{
    // the node classes as accepted, as `rosarch export nodl` writes them
    const NodlWriter::Documents nodl = NodlWriter::write(m_document->accepted().nodes);
    QString error;
    if (!NodlWriter::writeTo(nodl, folder, &error)) {
        showError(tr("Export failed"), tr("The NoDL descriptions could not be written:\n%1\n\n"
                                          "Choose a folder you can write to, and export again.")
                                           .arg(error));
        m_logView->appendLog(tr("NoDL export to %1 failed: %2").arg(folder, error));
        return false;
    }
    const QString message =
        tr("Exported %n NoDL descriptions to %1", nullptr, int(nodl.files.size()))
            .arg(QDir::toNativeSeparators(folder));
    m_logView->appendLog(message);
    for (const QString &line : nodl.omitted)
        m_logView->appendLog(tr("NoDL: %1").arg(line));
    statusBar()->showMessage(message, 5000);
    return true;
}

} // namespace rosarch
