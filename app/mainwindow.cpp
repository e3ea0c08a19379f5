#include "app/mainwindow.h"
#include "app/aboutdialog.h"
#include "app/appsettings.h"
#include "app/comparecontroller.h"
#include "app/diagramcontroller.h"
#include "app/diagramfocus.h"
#include "app/navigationcontroller.h"
#include "app/parametercontroller.h"
#include "app/projectcontroller.h"
#include "app/rendercontroller.h"
#include "app/stagecontroller.h"
#include "app/stagerunner.h"
#include "app/suggestioncontroller.h"
#include "app/traceability.h"
#include "app/workspacewatcher.h"
#include "artifacts/artifactwriter.h"
#include "diagram/diagramlayouter.h"
#include "document/document.h"
#include "project/project.h"
#include "widgets/architecturediffview.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/icons.h"
#include "widgets/launchargumentsdialog.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/parameterpanel.h"
#include "widgets/sourceview.h"
#include "widgets/suggestionmodel.h"
#include "widgets/suggestionpanel.h"
#include "widgets/talkerspanel.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QScreen>
#include <QStatusBar>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <QUndoStack>

#include <algorithm>

namespace rosarch {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_document(new Document(this)), m_runner(new StageRunner(this)),
      m_nodeModel(new AtomicNodeModel(m_document, this)),
      m_launchModel(new LaunchTreeModel(m_document, this)),
      m_diagnosticModel(new DiagnosticModel(m_document, this))
{
    setWindowTitle(tr("rosarch[*]"));
    setWindowIcon(Icons::application());
    setAcceptDrops(true);
    setDockNestingEnabled(true);

    createPanels();
    Icons::warmUp(this); // before the first result is painted
    m_stages = new StageController(m_document, m_runner, m_traceability, m_logView, this);
    m_watcher = new WorkspaceWatcher(this);
    m_watcher->setEnabled(AppSettings().watchWorkspace());
    connect(m_watcher, &WorkspaceWatcher::rerunRequested, this,
            [this](WorkspaceWatcher::Rerun rerun, const QStringList &files) {
                statusBar()->showMessage(tr("%n file(s) changed on disk (%1); analysing again",
                                            nullptr, int(files.size()))
                                             .arg(files.mid(0, 3).join(QLatin1String(", "))),
                                         5000);
                if (rerun == WorkspaceWatcher::Rerun::Launch)
                    m_stages->runLaunch();
                else
                    m_stages->runAll();
            });
    // Past the bound only folders are watched: edits in place go unseen, so say it once.
    connect(m_watcher, &WorkspaceWatcher::watching, this, [this] {
        if (m_watcher->watchesFiles() || m_foldersOnlyNoted == m_watcher->workspace())
            return;
        m_foldersOnlyNoted = m_watcher->workspace();
        m_logView->appendLog(
            tr("This workspace has more than %L1 files and folders to watch, so only its "
               "folders are watched: files added, removed or replaced (as most editors save) "
               "start a new analysis, a file edited in place does not. Press F5 after such an "
               "edit.")
                .arg(WorkspaceWatcher::kMaxWatchedPaths));
    });
    createActions();
    createMenus();
    createStatusBar();

    connect(m_stages, &StageController::statusMessage, statusBar(), &QStatusBar::showMessage);
    connect(m_runner, &StageRunner::stageStarted, this, &MainWindow::onStageStarted);
    connect(m_runner, &StageRunner::stageProgressed, this, &MainWindow::onStageProgressed);
    connect(m_runner, &StageRunner::stageFinished, this, [this] {
        m_runStopped = false;
        setRunning(false);
    });
    connect(m_runner, &StageRunner::launchStageFinished, this, [this] {
        m_runStopped = false;
        setRunning(false);
    });
    connect(m_runner, &StageRunner::stageCanceled, this, [this] {
        m_runStopped = true;
        setRunning(false);
    });
    connect(m_runner, &StageRunner::stageFailed, this, [this] {
        m_runStopped = true;
        setRunning(false);
    });
    const auto filesMayHaveChanged = [this] {
        // The files may have changed since they were shown; start the source view afresh.
        m_sourceView->setWorkspaceRoot(m_document->workspaceRoot());
        m_sourceView->clear();
        updateCounts();
    };
    connect(m_document, &Document::changed, this, [filesMayHaveChanged](const DocumentChange &c) {
        if (c.parts & (DocumentChange::Model | DocumentChange::Launch))
            filesMayHaveChanged();
    });

    connect(m_document->session(), &ProjectSession::modifiedChanged, this,
            &QWidget::setWindowModified);
    connect(m_document->session(), &ProjectSession::projectPathChanged, this,
            &MainWindow::updateTitle);
    connect(m_projects, &ProjectController::workspaceRequested, this,
            &MainWindow::openWorkspaceNow);
    connect(m_projects, &ProjectController::launchOptionsReplaced, this,
            &MainWindow::runLaunchStage);
    connect(m_projects, &ProjectController::statusMessage, statusBar(), &QStatusBar::showMessage);

    restoreSession();
    updateCounts();
    setRunning(false);
}

MainWindow::~MainWindow() = default;

QString MainWindow::workspace() const
{
    return m_stages->workspace();
}

void MainWindow::createPanels()
{
    m_nodePanel = new AtomicNodePanel(this);
    m_nodePanel->setModel(m_nodeModel);
    m_launchPanel = new LaunchTreePanel(this);
    m_launchPanel->setModel(m_launchModel);
    m_diagramLayouter = new DiagramLayouter(this);
    m_diagramPanel = new DiagramPanel(m_diagramLayouter, this);
    m_sourceView = new SourceView(this);
    m_logView = new LogView(this);
    m_logView->setModel(m_diagnosticModel);
    // Folders dropped anywhere open a workspace; the text views must not swallow them.
    m_sourceView->editor()->setAcceptDrops(false);
    m_sourceView->editor()->viewport()->setAcceptDrops(false);
    m_logView->logEdit()->setAcceptDrops(false);
    m_logView->logEdit()->viewport()->setAcceptDrops(false);

    const auto makeDock = [this](QWidget *widget, const QString &title, const QString &name) {
        auto *dock = new QDockWidget(title, this);
        dock->setObjectName(name);
        dock->setWidget(widget);
        dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                          QDockWidget::DockWidgetFloatable);
        return dock;
    };
    m_nodeDock = makeDock(m_nodePanel, tr("Atomic nodes"), QStringLiteral("atomicNodesDock"));
    m_launchDock = makeDock(m_launchPanel, tr("Launch tree"), QStringLiteral("launchTreeDock"));
    m_diagramDock = makeDock(m_diagramPanel, tr("Composed diagram"), QStringLiteral("diagramDock"));
    m_sourceDock = makeDock(m_sourceView, tr("Source"), QStringLiteral("sourceDock"));
    m_logDock = makeDock(m_logView, tr("Log"), QStringLiteral("logDock"));
    // The title (and its tab) counts the findings; the View menu keeps saying "Log".
    connect(m_logView, &LogView::titleChanged, m_logDock, [this](const QString &title) {
        m_logDock->setWindowTitle(title);
        m_logDock->toggleViewAction()->setText(tr("Log"));
    });
    m_suggestionModel = new SuggestionModel(m_document, this);
    m_suggestionPanel = new SuggestionPanel(this);
    m_suggestionPanel->setModel(m_suggestionModel);
    m_suggestionDock =
        makeDock(m_suggestionPanel, tr("Suggestions"), QStringLiteral("suggestionsDock"));
    m_changesView = new ArchitectureDiffView(this);
    m_changesDock =
        makeDock(m_changesView, tr("Architecture changes"), QStringLiteral("changesDock"));
    m_talkersPanel = new TalkersPanel(this);
    m_talkersDock = makeDock(m_talkersPanel, tr("Talkers"), QStringLiteral("talkersDock"));
    m_parameterPanel = new ParameterPanel(this);
    m_parameterDock =
        makeDock(m_parameterPanel, tr("Parameters"), QStringLiteral("parametersDock"));
    createCorrectionDocks();
    resetLayout();

    m_traceability = new Traceability(m_nodeModel, m_nodePanel, m_launchModel, m_launchPanel,
                                      m_sourceView, this);
    connect(m_nodePanel, &AtomicNodePanel::evidenceRequested, m_traceability,
            &Traceability::showEvidence);
    connect(m_traceability, &Traceability::evidenceUnavailable, this,
            [this](const Evidence &evidence) {
                statusBar()->showMessage(tr("Cannot show %1").arg(evidence.file), 5000);
            });
    connect(m_launchPanel, &LaunchTreePanel::classRequested, this, [this] {
        m_nodeDock->show();
        m_nodeDock->raise();
    });
    connect(m_logView, &LogView::evidenceRequested, m_traceability, &Traceability::showEvidence);
    new ParameterController(m_document, m_nodeModel, m_nodePanel, m_launchModel, m_launchPanel,
                            m_parameterPanel, m_traceability, this);
    connect(m_logView, &LogView::externalsAccepted, this, &MainWindow::acceptExternals);
    m_diagrams = new DiagramController(m_document, m_diagramPanel, m_launchPanel, m_traceability,
                                       m_talkersPanel, m_logView, this);
    connect(m_diagrams, &DiagramController::statusMessage, statusBar(), &QStatusBar::showMessage);
    connect(m_diagrams, &DiagramController::talkersShown, this, [this] {
        m_talkersDock->show();
        m_talkersDock->raise();
    });

    m_suggestions = new SuggestionController(m_document, m_suggestionPanel, this);
    m_suggestions->setPreviews({[this](const Evidence &e) { m_traceability->showEvidence(e); },
                                [this](const QString &arcId) { m_traceability->selectNode(arcId); },
                                [this](const QStringList &ids) {
                                    if (!ids.isEmpty())
                                        m_traceability->selectLaunchItem(ids.first());
                                }});
    // A pending suggestion is previewed where it would land: a description in the node
    // list, a grouping in the composed diagram. The model changes only on Accept.
    const auto preview = [this](const QString &id) {
        const Suggestion *s = m_document->session()->suggestion(id);
        const bool pending = s && s->status == Suggestion::Status::Pending;
        if (pending && s->kind == Suggestion::Kind::SubsystemGrouping)
            m_diagrams->previewGrouping(s->value, s->memberIds, s->targetId);
        else
            m_diagrams->previewGrouping({}, {}, {});
        if (pending && s->kind == Suggestion::Kind::NodeDescription)
            m_nodeModel->setDescriptionPreview(s->targetId, s->value);
        else
            m_nodeModel->setDescriptionPreview({}, {});
    };
    connect(m_suggestionPanel, &SuggestionPanel::currentSuggestionChanged, this, preview);
    connect(m_document, &Document::changed, this, [this, preview](const DocumentChange &c) {
        // accepted or rejected: no preview
        if (c.has(DocumentChange::Suggestion) && c.id == m_suggestionPanel->currentSuggestionId())
            preview(c.id);
    });
    m_compare = new CompareController(m_document, m_changesView, m_changesDock, m_logView, this);
    m_render = new RenderController(m_document, m_logView, this);
    connect(m_render, &RenderController::status, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
    connect(m_suggestions, &SuggestionController::logged, m_logView, &LogView::appendLog);
    connect(m_suggestions, &SuggestionController::statusMessage, statusBar(),
            &QStatusBar::showMessage);
    createCorrectionController();
}

void MainWindow::takeOutDock(QDockWidget *dock)
{
    // Docked first, then taken out: a floating dock taken out stays a window of its own when
    // it is split or tabified in again (Reset Layout left a floated Log floating).
    dock->setFloating(false);
    removeDockWidget(dock);
}

void MainWindow::resetLayout()
{
    if (m_diagramFocus)
        m_diagramFocus->setFocused(false); // the panels it hid come back with the rest
    const QList<QDockWidget *> docks{m_nodeDock,   m_launchDock, m_diagramDock,
                                     m_sourceDock, m_logDock,    m_suggestionDock};
    for (QDockWidget *dock : docks)
        takeOutDock(dock);
    // One nested dock area fills the window (there is no central widget): the model views
    // side by side on top (atomic nodes | launch tree | diagram | source), the log across the
    // bottom. Growing the window grows them all. In a small window the Log takes the whole bottom
    // row, Suggestions a tab beside it: side by side at 1024 px its filter bar took three lines and
    // the table showed two findings.
    const bool small = isSmallLayout(size());
    addDockWidget(Qt::TopDockWidgetArea, m_nodeDock);
    splitDockWidget(m_nodeDock, small ? m_logDock : m_suggestionDock, Qt::Vertical);
    if (small)
        tabifyDockWidget(m_logDock, m_suggestionDock);
    else
        splitDockWidget(m_suggestionDock, m_logDock, Qt::Horizontal);
    splitDockWidget(m_nodeDock, m_launchDock, Qt::Horizontal);
    splitDockWidget(m_launchDock, m_diagramDock, Qt::Horizontal);
    splitDockWidget(m_diagramDock, m_sourceDock, Qt::Horizontal);
    for (QDockWidget *dock : docks)
        dock->show();
    // Architecture changes and talkers share the log's place and appear when a comparison
    // runs or a topic, service, action or port is clicked; the parameters of what is selected
    // are a tab there from the start.
    for (QDockWidget *dock : {m_changesDock, m_talkersDock, m_parameterDock}) {
        if (!dock)
            continue;
        takeOutDock(dock);
        tabifyDockWidget(m_logDock, dock);
        dock->setVisible(dock == m_parameterDock);
    }
    placeCorrectionDocks();
    m_logDock->raise();
    if (m_toolBar)
        m_toolBar->show();
    const int w = std::max(width(), 800);
    const int h = std::max(height(), 600);
    resizeDocks({m_nodeDock, m_launchDock, m_diagramDock, m_sourceDock},
                {w * 2 / 10, w * 2 / 10, w * 4 / 10, w * 2 / 10}, Qt::Horizontal);
    if (small) {
        resizeDocks({m_nodeDock, m_logDock}, {h * 6 / 10, h * 4 / 10}, Qt::Vertical);
        return;
    }
    resizeDocks({m_nodeDock, m_suggestionDock}, {h * 7 / 10, h * 3 / 10}, Qt::Vertical);
    resizeDocks({m_suggestionDock, m_logDock}, {w / 2, w / 2}, Qt::Horizontal);
}

void MainWindow::restoreSession()
{
    m_defaultState = saveState();
    AppSettings settings;
    const QByteArray geometry = settings.windowGeometry();
    if (geometry.isEmpty() || !restoreGeometry(geometry)) {
        const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 1600, 1000);
        // A small screen is given whole: nine tenths of 1024 x 700 left the docks too little.
        const bool smallScreen = available.width() < 1280 || available.height() < 800;
        if (smallScreen)
            setGeometry(available);
        else
            resize(std::min(1440, available.width() * 9 / 10),
                   std::min(900, available.height() * 9 / 10));
        resetLayout();
        m_defaultState = saveState();
    }
    // A layout saved in a window of the other size class (the large one's side-by-side Log on
    // a small screen) would be cramped: the layout of this size is made instead.
    const QSize savedAt = settings.windowStateSize();
    if (!savedAt.isValid() || isSmallLayout(savedAt) == isSmallLayout(size()))
        restoreState(settings.windowState());
    else
        resetLayout();
    m_logView->filterBar()->restoreState(settings.logFilter());
}

bool MainWindow::isSmallLayout(const QSize &size)
{
    return size.width() < 1280 || size.height() < 800;
}

void MainWindow::saveSession()
{
    if (m_diagramFocus)
        m_diagramFocus->setFocused(false); // the layout to come back to, not the focus
    AppSettings settings;
    settings.setWindowGeometry(saveGeometry());
    settings.setWindowState(saveState());
    settings.setWindowStateSize(size());
    settings.setLogFilter(m_logView->filterBar()->state());
    if (!workspace().isEmpty()) {
        settings.setSelection(workspace(), m_traceability->currentNodeId(),
                              m_traceability->currentPortId());
        settings.setLaunchSelection(workspace(), m_traceability->currentLaunchId());
    }
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSession();
    if (!m_closeConfirmed && m_document->session()->isModified()) {
        // Save / Discard / Cancel without blocking: the window closes once it is answered.
        event->ignore();
        m_projects->maybeSave([this] {
            m_closeConfirmed = true;
            close();
        });
        return;
    }
    m_closeConfirmed = false;
    m_runner->cancel();
    QMainWindow::closeEvent(event);
}

void MainWindow::dragEnterEvent(QDragEnterEvent *event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.size() == 1 && urls.first().isLocalFile() &&
        QFileInfo(urls.first().toLocalFile()).isDir())
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent *event)
{
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty())
        return;
    event->acceptProposedAction();
    openWorkspace(urls.first().toLocalFile());
}

void MainWindow::openWorkspaceDialog()
{
    const QString start = workspace().isEmpty() ? QDir::homePath() : workspace();
    const QString folder = QFileDialog::getExistingDirectory(this, tr("Open ROS 2 Workspace"),
                                                             start, QFileDialog::ShowDirsOnly);
    if (!folder.isEmpty())
        openWorkspace(folder);
}

void MainWindow::openWorkspace(const QString &path)
{
    const QFileInfo info(path);
    if (path.isEmpty() || !info.isDir()) {
        AppSettings().removeRecentWorkspace(path);
        showError(tr("Cannot open workspace"),
                  tr("The folder “%1” does not exist or is not a folder.\n\n"
                     "Choose a ROS 2 workspace (a folder containing packages with a "
                     "package.xml) with File → Open Workspace, or drop one onto the window.")
                      .arg(QDir::toNativeSeparators(path)));
        return;
    }
    const QString root = info.canonicalFilePath();
    if (root == workspace())
        openWorkspaceNow(root); // the same project, run again
    else
        m_projects->maybeSave([this, root] { openWorkspaceNow(root); });
}

void MainWindow::openWorkspaceNow(const QString &root)
{
    const bool another = root != workspace();
    // Keep the old result only while re-running the same workspace.
    if (another && !workspace().isEmpty())
        saveSession();
    m_stages->setWorkspace(root);
    m_watcher->setWorkspace(root);
    AppSettings settings;
    settings.addRecentWorkspace(root);
    settings.setLastWorkspace(root);
    updateTitle();
    setWindowFilePath(root);
    if (another) {
        m_projects->projectOpened();
        m_navigation->clear(); // the places were another workspace's
    }
    runAllStages();
}

void MainWindow::updateTitle()
{
    const QString root = m_document->workspaceRoot();
    if (root.isEmpty()) {
        setWindowTitle(tr("rosarch[*]"));
        return;
    }
    const QString file = m_document->session()->projectPath();
    const QString ws = QFileInfo(root).fileName();
    // The project is named when it is not the workspace's own (or the one kept for it).
    QString title = ws;
    if (m_document->session()->isUntitled())
        title = tr("%1 (new project)").arg(ws);
    else if (file != ProjectFile::defaultPath(root) && file != ProjectFile::appDataPath(root))
        title = tr("%1 (%2)").arg(ws, QFileInfo(file).fileName());
    setWindowTitle(tr("%1[*] — rosarch").arg(title));
    setWindowModified(m_document->session()->isModified());
}

void MainWindow::runAllStages()
{
    if (workspace().isEmpty())
        openWorkspaceDialog();
    else
        m_stages->runAll();
}

void MainWindow::runLaunchStage()
{
    if (workspace().isEmpty())
        openWorkspaceDialog();
    else
        m_stages->runLaunch();
}

void MainWindow::acceptExternals(const QStringList &declarations)
{
    LaunchOptions options = m_document->session()->launchOptions();
    QStringList names;
    for (const QString &d : declarations) {
        const qsizetype space = d.indexOf(QLatin1Char(' '));
        const ExpectedExternal e{d.mid(space + 1), d.startsWith(QLatin1String("output")),
                                 tr("accepted in the Log")};
        const bool declared = std::any_of(
            options.externals.cbegin(), options.externals.cend(),
            [&](const ExpectedExternal &x) { return x.name == e.name && x.output == e.output; });
        if (space < 0 || declared)
            continue;
        options.externals.append(e);
        names << e.name;
    }
    if (names.isEmpty())
        return;
    statusBar()->showMessage(
        tr("Declared %1 as expected external; checking again.").arg(names.join(tr(", "))), 8000);
    applyLaunchOptions(options);
}

void MainWindow::applyLaunchOptions(const LaunchOptions &options)
{
    m_stages->applyLaunchOptions(options);
}

void MainWindow::showLaunchArgumentsDialog()
{
    auto *dialog = new LaunchArgumentsDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setLaunchDependencies(m_document->launchDependencies(),
                                  m_document->session()->launchOptions().rootFile);
    dialog->setOptions(m_document->session()->launchOptions());
    connect(dialog, &QDialog::accepted, this,
            [this, dialog] { applyLaunchOptions(dialog->options()); });
    dialog->open();
}

void MainWindow::updateRecentMenu()
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
        connect(action, &QAction::triggered, this, [this, path] { openWorkspace(path); });
    }
    m_recentMenu->addSeparator();
    connect(m_recentMenu->addAction(tr("&Clear Menu")), &QAction::triggered, this,
            [] { AppSettings().clearRecentWorkspaces(); });
}

void MainWindow::exportArtifactsDialog()
{
    AppSettings settings;
    QString start = settings.lastExportFolder();
    if (start.isEmpty())
        start = workspace().isEmpty() ? QDir::homePath() : QFileInfo(workspace()).path();
    const QString folder =
        QFileDialog::getExistingDirectory(this, tr("Export Artifacts To"), start);
    if (folder.isEmpty())
        return;
    settings.setLastExportFolder(folder);
    exportArtifactsTo(folder);
}

bool MainWindow::exportArtifactsTo(const QString &folder)
{
    QStringList written;
    QString error, notice;
    // The model as accepted: accepted groupings are nested composites in the CCDs, accepted
    // names resolve ports, exactly as `rosarch recover` writes it for the same decisions.
    if (!ArtifactWriter::writeAll(m_document->accepted(), folder, &written, &error, {}, &notice)) {
        showError(tr("Export failed"),
                  tr("The artifacts could not be written to “%1”:\n%2\n\n"
                     "Choose a folder you can write to, or free some space, and export again.")
                      .arg(QDir::toNativeSeparators(folder), error));
        m_logView->appendLog(tr("Export to %1 failed: %2").arg(folder, error));
        return false;
    }
    const QString message = written.size() == 1 ? tr("Exported 1 file to %1")
                                                : tr("Exported %1 files to %2").arg(written.size());
    m_logView->appendLog(message.arg(QDir::toNativeSeparators(folder)));
    if (!notice.isEmpty())
        m_logView->appendLog(notice);
    statusBar()->showMessage(message.arg(QDir::toNativeSeparators(folder)), 5000);
    return true;
}

void MainWindow::showError(const QString &title, const QString &text)
{
    // Window-modal but not blocking: the caller (and an offscreen test) carries on.
    auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace rosarch
