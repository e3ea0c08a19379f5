#include "app/mainwindow.h"
#include "app/appsettings.h"
#include "app/changeselector.h"
#include "app/comparecontroller.h"
#include "app/correctioncontroller.h"
#include "app/diagramcontroller.h"
#include "app/exportcontroller.h"
#include "app/mainmenus.h"
#include "app/navigationcontroller.h"
#include "app/paneldocks.h"
#include "app/parametercontroller.h"
#include "app/projectcontroller.h"
#include "app/rendercontroller.h"
#include "app/stagecontroller.h"
#include "app/stagerunner.h"
#include "app/statuspresenter.h"
#include "app/suggestioncontroller.h"
#include "app/traceability.h"
#include "app/workspacewatcher.h"
#include "document/document.h"
#include "pipeline/recovery.h"
#include "project/project.h"
#include "widgets/architecturediffview.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/correctionmodel.h"
#include "widgets/correctionpanel.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/icons.h"
#include "widgets/inspectorpanel.h"
#include "widgets/launchargumentsdialog.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/parameterpanel.h"
#include "widgets/sourceview.h"
#include "widgets/suggestionmodel.h"
#include "widgets/suggestionpanel.h"
#include "widgets/talkerspanel.h"

#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>

#include <algorithm>

namespace rosarch {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_document(new Document(this)), m_runner(new StageRunner(this)),
      m_nodeModel(new AtomicNodeModel(m_document, this)),
      m_launchModel(new LaunchTreeModel(m_document, this)),
      m_diagnosticModel(new DiagnosticModel(m_document, this)),
      m_suggestionModel(new SuggestionModel(m_document, this)),
      m_correctionModel(new CorrectionModel(m_document, this))
{
    setWindowTitle(tr("rosarch[*]"));
    setWindowIcon(Icons::application());
    setAcceptDrops(true);
    setDockNestingEnabled(true);

    m_docks = new PanelDocks(this);
    m_docks->nodePanel()->setModel(m_nodeModel);
    m_docks->launchPanel()->setModel(m_launchModel);
    m_docks->logView()->setModel(m_diagnosticModel);
    m_docks->suggestionPanel()->setModel(m_suggestionModel);
    m_docks->correctionPanel()->setModel(m_correctionModel);
    createControllers();
    Icons::warmUp(this); // before the first result is painted
    m_stages = new StageController(m_document, m_runner, m_traceability, m_docks->logView(), this);
    createWatcher();
    m_projects = new ProjectController(m_document, m_docks->logView(), this);
    m_navigation = new NavigationController(m_document,
                                            {m_docks->nodePanel(), m_docks->launchPanel(),
                                             m_docks->diagramPanel(), m_docks->sourceView(),
                                             m_docks->logView()},
                                            this);
    auto *changes = new ChangeSelector(m_document, m_docks->changesView(), m_traceability,
                                       m_docks->diagramPanel(), this);
    connect(changes, &ChangeSelector::statusMessage, statusBar(), &QStatusBar::showMessage);

    m_exports = new ExportController(this, m_document, m_stages, m_docks->logView());
    m_menus =
        new MainMenus(this, {m_document, m_runner, m_docks, m_watcher, m_projects, m_navigation,
                             m_diagrams, m_render, m_compare, m_suggestions, m_corrections});
    connect(m_menus, &MainMenus::openWorkspaceRequested, this, &MainWindow::openWorkspaceDialog);
    connect(m_menus, &MainMenus::workspaceRequested, this, &MainWindow::openWorkspace);
    connect(m_menus, &MainMenus::exportArtifactsRequested, m_exports,
            &ExportController::exportArtifactsDialog);
    connect(m_menus, &MainMenus::exportNodlRequested, m_exports,
            &ExportController::exportNodlDialog);
    connect(m_menus, &MainMenus::exportSiteRequested, m_exports,
            &ExportController::exportSiteDialog);
    connect(m_menus, &MainMenus::runAllRequested, this, &MainWindow::runAllStages);
    connect(m_menus, &MainMenus::runLaunchRequested, this, &MainWindow::runLaunchStage);
    connect(m_menus, &MainMenus::launchArgumentsRequested, this,
            &MainWindow::showLaunchArgumentsDialog);
    m_status =
        new StatusPresenter(this, m_document, m_runner, m_stages, m_docks, m_menus->cancelAction());

    connect(m_stages, &StageController::statusMessage, statusBar(), &QStatusBar::showMessage);
    const auto filesMayHaveChanged = [this] {
        // The files may have changed since they were shown; start the source view afresh.
        m_docks->sourceView()->setWorkspaceRoot(m_document->workspaceRoot());
        m_docks->sourceView()->clear();
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

    m_docks->restoreLayout();
    updateCounts();
    m_status->setRunning(false);
}

MainWindow::~MainWindow() = default;

QString MainWindow::workspace() const
{
    return m_stages->workspace();
}

void MainWindow::createControllers()
{
    AtomicNodePanel *nodePanel = m_docks->nodePanel();
    LaunchTreePanel *launchPanel = m_docks->launchPanel();
    DiagramPanel *diagramPanel = m_docks->diagramPanel();
    LogView *logView = m_docks->logView();
    SuggestionPanel *suggestionPanel = m_docks->suggestionPanel();
    m_traceability = new Traceability(m_nodeModel, nodePanel, m_launchModel, launchPanel,
                                      m_docks->sourceView(), this);
    connect(nodePanel, &AtomicNodePanel::evidenceRequested, m_traceability,
            &Traceability::showEvidence);
    connect(m_traceability, &Traceability::evidenceUnavailable, this,
            [this](const Evidence &evidence) {
                statusBar()->showMessage(tr("Cannot show %1").arg(evidence.file), 5000);
            });
    connect(launchPanel, &LaunchTreePanel::classRequested, this,
            [this] { m_docks->bringForward(PanelDocks::Dock::Nodes); });
    connect(logView, &LogView::evidenceRequested, m_traceability, &Traceability::showEvidence);
    new ParameterController(m_document, m_nodeModel, nodePanel, m_launchModel, launchPanel,
                            m_docks->parameterPanel(), m_traceability, this);
    connect(logView, &LogView::externalsAccepted, this, &MainWindow::acceptExternals);
    m_diagrams = new DiagramController(m_document, diagramPanel, launchPanel, m_traceability,
                                       m_docks->talkersPanel(), logView, this);
    connect(m_diagrams, &DiagramController::statusMessage, statusBar(), &QStatusBar::showMessage);
    connect(m_diagrams, &DiagramController::talkersShown, this,
            [this] { m_docks->bringForward(PanelDocks::Dock::Talkers); });

    m_suggestions = new SuggestionController(m_document, suggestionPanel, this);
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
    connect(suggestionPanel, &SuggestionPanel::currentSuggestionChanged, this, preview);
    connect(
        m_document, &Document::changed, this, [suggestionPanel, preview](const DocumentChange &c) {
            // accepted or rejected: no preview
            if (c.has(DocumentChange::Suggestion) && c.id == suggestionPanel->currentSuggestionId())
                preview(c.id);
        });
    m_compare = new CompareController(m_document, m_docks->changesView(),
                                      m_docks->dock(PanelDocks::Dock::Changes), logView, this);
    m_render = new RenderController(m_document, logView, this);
    connect(m_render, &RenderController::status, this,
            [this](const QString &message) { statusBar()->showMessage(message, 8000); });
    connect(m_suggestions, &SuggestionController::logged, logView, &LogView::appendLog);
    connect(m_suggestions, &SuggestionController::statusMessage, statusBar(),
            &QStatusBar::showMessage);

    CorrectionPanel *correctionPanel = m_docks->correctionPanel();
    m_corrections =
        new CorrectionController(m_document, nodePanel, launchPanel, diagramPanel, m_traceability,
                                 m_docks->inspector(), correctionPanel, this);
    connect(m_corrections, &CorrectionController::statusMessage, statusBar(),
            &QStatusBar::showMessage);
    connect(m_document, &Document::changed, this,
            [this, correctionPanel](const DocumentChange &change) {
                // a new correction is listed where a person can see and revert it; the views stay
                // where the person is (showing its element would move them)
                if (change.has(DocumentChange::Corrections) &&
                    m_document->session()->correction(change.id))
                    correctionPanel->listCorrection(change.id);
            });
}

void MainWindow::createWatcher()
{
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
        m_docks->logView()->appendLog(
            tr("This workspace has more than %L1 files and folders to watch, so only its "
               "folders are watched: files added, removed or replaced (as most editors save) "
               "start a new analysis, a file edited in place does not. Press F5 after such an "
               "edit.")
                .arg(WorkspaceWatcher::kMaxWatchedPaths));
    });
}

void MainWindow::updateCounts()
{
    const RecoveryCounts counts = m_status->updateCounts();
    m_menus->enableForResult(!m_document->atomicNodes().workspaceRoot.isEmpty(),
                             counts.diagnostics);
}

void MainWindow::saveSession()
{
    m_docks->saveLayout();
    if (!workspace().isEmpty()) {
        AppSettings settings;
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

bool MainWindow::exportArtifactsTo(const QString &folder)
{
    return m_exports->exportArtifactsTo(folder);
}

bool MainWindow::exportNodlTo(const QString &folder)
{
    return m_exports->exportNodlTo(folder);
}

void MainWindow::showError(const QString &title, const QString &text)
{
    // Window-modal but not blocking: the caller (and an offscreen test) carries on.
    auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace rosarch
