#include "mainwindow.h"
#include "aboutdialog.h"
#include "appsettings.h"
#include "artifactwriter.h"
#include "atomicnodemodel.h"
#include "atomicnodepanel.h"
#include "diagnosticmodel.h"
#include "document.h"
#include "icons.h"
#include "logview.h"
#include "sourceview.h"
#include "stagerunner.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
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

// The resources live in this static library; make sure the linker keeps them.
static void initResources()
{
    Q_INIT_RESOURCE(resources);
}

namespace rosarch {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_document(new Document(this)), m_runner(new StageRunner(this)),
      m_nodeModel(new AtomicNodeModel(m_document, this)),
      m_diagnosticModel(new DiagnosticModel(m_document, this))
{
    initResources();
    setWindowTitle(tr("rosarch"));
    setWindowIcon(Icons::application());
    setAcceptDrops(true);
    setDockNestingEnabled(true);

    createPanels();
    createActions();
    createMenus();
    createStatusBar();

    connect(m_runner, &StageRunner::stageStarted, this, &MainWindow::onStageStarted);
    connect(m_runner, &StageRunner::stageProgressed, this, &MainWindow::onStageProgressed);
    connect(m_runner, &StageRunner::stageFinished, this, &MainWindow::onStageFinished);
    connect(m_runner, &StageRunner::stageCanceled, this, &MainWindow::onStageCanceled);
    connect(m_document, &Document::modelReset, this, [this] {
        // The files may have changed since they were shown; start the source view afresh.
        m_sourceView->setWorkspaceRoot(m_document->workspaceRoot());
        m_sourceView->clear();
        updateCounts();
    });

    restoreSession();
    updateCounts();
    setRunning(false);
}

MainWindow::~MainWindow() = default;

void MainWindow::createPanels()
{
    m_nodePanel = new AtomicNodePanel(this);
    m_nodePanel->setModel(m_nodeModel);
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
    m_sourceDock = makeDock(m_sourceView, tr("Source"), QStringLiteral("sourceDock"));
    m_logDock = makeDock(m_logView, tr("Log"), QStringLiteral("logDock"));
    resetLayout();

    connect(m_nodePanel, &AtomicNodePanel::currentSourceIndexChanged, this,
            &MainWindow::onNodeSelected);
    connect(m_sourceView, &SourceView::cursorLineChanged, this, &MainWindow::onSourceLineChanged);
    connect(m_logView, &LogView::evidenceRequested, this, &MainWindow::showEvidence);
}

void MainWindow::resetLayout()
{
    for (QDockWidget *dock : {m_nodeDock, m_sourceDock, m_logDock}) {
        removeDockWidget(dock);
        dock->setFloating(false);
    }
    // One nested dock area fills the window (there is no central widget): the model views
    // side by side on top, the log across the bottom. Growing the window grows them all.
    addDockWidget(Qt::TopDockWidgetArea, m_nodeDock);
    splitDockWidget(m_nodeDock, m_logDock, Qt::Vertical);
    splitDockWidget(m_nodeDock, m_sourceDock, Qt::Horizontal);
    for (QDockWidget *dock : {m_nodeDock, m_sourceDock, m_logDock})
        dock->show();
    if (m_toolBar)
        m_toolBar->show();
    const int w = std::max(width(), 800);
    const int h = std::max(height(), 600);
    resizeDocks({m_nodeDock, m_sourceDock}, {w * 11 / 20, w * 9 / 20}, Qt::Horizontal);
    resizeDocks({m_nodeDock, m_logDock}, {h * 4 / 5, h / 5}, Qt::Vertical);
}

void MainWindow::createActions()
{
    m_openAction = new QAction(Icons::open(), tr("&Open Workspace…"), this);
    m_openAction->setShortcut(QKeySequence::Open);
    m_openAction->setStatusTip(tr("Open a ROS 2 workspace folder and recover its architecture"));
    connect(m_openAction, &QAction::triggered, this, &MainWindow::openWorkspaceDialog);

    m_exportAction = new QAction(tr("&Export Artifacts…"), this);
    m_exportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    m_exportAction->setStatusTip(
        tr("Write atomic_nodes.json, diagnostics.json and one PlantUML diagram per node"));
    connect(m_exportAction, &QAction::triggered, this, &MainWindow::exportArtifactsDialog);

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
    m_findAction->setStatusTip(tr("Filter the node tree by name or type"));
    connect(m_findAction, &QAction::triggered, this, [this] {
        m_nodeDock->show();
        m_nodeDock->raise();
        m_nodePanel->focusFilter();
    });

    m_nextDiagnosticAction = new QAction(tr("&Next Diagnostic"), this);
    m_nextDiagnosticAction->setShortcut(QKeySequence(Qt::Key_F8));
    connect(m_nextDiagnosticAction, &QAction::triggered, this, [this] {
        m_logDock->show();
        m_logView->selectNextDiagnostic();
    });
    m_previousDiagnosticAction = new QAction(tr("&Previous Diagnostic"), this);
    m_previousDiagnosticAction->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F8));
    connect(m_previousDiagnosticAction, &QAction::triggered, this, [this] {
        m_logDock->show();
        m_logView->selectPreviousDiagnostic();
    });

    m_runAction = new QAction(Icons::run(), tr("Run Stage &1: Atomic Nodes"), this);
    m_runAction->setIconText(tr("Run"));
    m_runAction->setShortcut(QKeySequence(Qt::Key_F5));
    m_runAction->setToolTip(tr("Recover the atomic nodes of the workspace (F5)"));
    m_runAction->setStatusTip(tr("Find node classes, their ports and their executables"));
    connect(m_runAction, &QAction::triggered, this, &MainWindow::runStage1);

    m_cancelAction = new QAction(Icons::stop(), tr("&Cancel Stage"), this);
    m_cancelAction->setIconText(tr("Cancel"));
    m_cancelAction->setShortcut(QKeySequence(Qt::Key_Escape));
    m_cancelAction->setToolTip(tr("Stop the running stage and keep the previous result (Esc)"));
    connect(m_cancelAction, &QAction::triggered, m_runner, &StageRunner::cancel);

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
    file->addAction(m_openAction);
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::updateRecentMenu);
    file->addSeparator();
    file->addAction(m_exportAction);
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
    m_toolBar->addAction(m_runAction);
    m_toolBar->addAction(m_cancelAction);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    for (QDockWidget *dock : {m_nodeDock, m_sourceDock, m_logDock})
        view->addAction(dock->toggleViewAction());
    m_toolBar->toggleViewAction()->setText(tr("&Toolbar"));
    view->addAction(m_toolBar->toggleViewAction());
    view->addSeparator();
    view->addAction(m_resetLayoutAction);

    QMenu *stages = menuBar()->addMenu(tr("&Stages"));
    stages->addAction(m_runAction);
    stages->addAction(m_cancelAction);

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    help->addAction(m_aboutAction);
    help->addAction(m_aboutQtAction);
}

void MainWindow::createStatusBar()
{
    m_countsLabel = new QLabel(this);
    m_progressBar = new QProgressBar(this);
    m_progressBar->setFixedWidth(220);
    m_progressBar->setMaximumHeight(16);
    m_progressBar->setTextVisible(false);
    m_cancelButton = new QToolButton(this);
    m_cancelButton->setDefaultAction(m_cancelAction);
    m_cancelButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_cancelButton->setAutoRaise(true);
    statusBar()->addPermanentWidget(m_countsLabel);
    statusBar()->addPermanentWidget(m_progressBar);
    statusBar()->addPermanentWidget(m_cancelButton);
}

void MainWindow::restoreSession()
{
    m_defaultState = saveState();
    AppSettings settings;
    const QByteArray geometry = settings.windowGeometry();
    if (geometry.isEmpty() || !restoreGeometry(geometry)) {
        const QRect available = screen() ? screen()->availableGeometry() : QRect(0, 0, 1600, 1000);
        resize(std::min(1440, available.width() * 9 / 10),
               std::min(900, available.height() * 9 / 10));
        resetLayout();
        m_defaultState = saveState();
    }
    restoreState(settings.windowState());
}

void MainWindow::saveSession()
{
    AppSettings settings;
    settings.setWindowGeometry(saveGeometry());
    settings.setWindowState(saveState());
    if (!m_workspace.isEmpty()) {
        const QModelIndex current = m_nodePanel->currentSourceIndex();
        settings.setSelection(m_workspace, current.data(AtomicNodeModel::NodeIdRole).toString(),
                              current.data(AtomicNodeModel::PortIdRole).toString());
    }
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    saveSession();
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
    const QString start = m_workspace.isEmpty() ? QDir::homePath() : m_workspace;
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
    if (root != m_workspace) {
        // Keep the old result only while re-running the same workspace.
        if (!m_workspace.isEmpty())
            saveSession();
        AtomicNodeList empty;
        empty.workspaceRoot = root;
        m_document->setAtomicNodes(empty);
        m_logView->clearLog();
        AppSettings().selection(root, &m_restoreNodeId, &m_restorePortId);
    }
    m_workspace = root;
    AppSettings settings;
    settings.addRecentWorkspace(root);
    settings.setLastWorkspace(root);
    setWindowTitle(tr("%1 — rosarch").arg(QFileInfo(root).fileName()));
    setWindowFilePath(root);
    runStage1();
}

void MainWindow::runStage1()
{
    if (m_workspace.isEmpty()) {
        openWorkspaceDialog();
        return;
    }
    if (m_restoreNodeId.isEmpty()) {
        const QModelIndex current = m_nodePanel->currentSourceIndex();
        m_restoreNodeId = current.data(AtomicNodeModel::NodeIdRole).toString();
        m_restorePortId = current.data(AtomicNodeModel::PortIdRole).toString();
    }
    m_runner->run(m_workspace);
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
        const QString path = recent[i];
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
        start = m_workspace.isEmpty() ? QDir::homePath() : QFileInfo(m_workspace).path();
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
    QString error;
    if (!ArtifactWriter::writeAll(m_document->atomicNodes(), folder, &written, &error)) {
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

void MainWindow::updateCounts()
{
    const AtomicNodeList &list = m_document->atomicNodes();
    int ports = 0;
    for (const AtomicNode &n : list.nodes)
        ports += int(n.ports.size());
    // Explicit singular/plural: no translator is loaded for English, so "%n node(s)" would show.
    const auto count = [](qsizetype n, const QString &one, const QString &many) {
        return n == 1 ? one : many.arg(n);
    };
    const QStringList parts{
        count(list.packages.size(), tr("1 package"), tr("%1 packages")),
        count(list.nodes.size(), tr("1 node"), tr("%1 nodes")),
        count(ports, tr("1 port"), tr("%1 ports")),
        count(list.diagnostics.size(), tr("1 diagnostic"), tr("%1 diagnostics"))};
    m_countsLabel->setText(parts.join(QStringLiteral(" · ")));
    m_exportAction->setEnabled(!list.workspaceRoot.isEmpty());
    m_nextDiagnosticAction->setEnabled(!list.diagnostics.isEmpty());
    m_previousDiagnosticAction->setEnabled(!list.diagnostics.isEmpty());
}

void MainWindow::setRunning(bool running)
{
    m_progressBar->setVisible(running);
    m_cancelButton->setVisible(running);
    m_cancelAction->setEnabled(running);
}

void MainWindow::onStageStarted(const QString &root)
{
    m_runTimer.start();
    m_lastProgressText.clear();
    m_progressBar->setRange(0, 0);
    setRunning(true);
    m_logView->appendLog(tr("Stage 1 (atomic nodes) started on %1").arg(root));
    statusBar()->showMessage(tr("Recovering atomic nodes…"));
}

void MainWindow::onStageProgressed(int done, int total, const QString &what)
{
    if (total > 0) {
        m_progressBar->setRange(0, total);
        m_progressBar->setValue(done);
    } else {
        m_progressBar->setRange(0, 0);
    }
    if (!what.isEmpty() && what != m_lastProgressText) {
        m_lastProgressText = what;
        statusBar()->showMessage(what);
        m_logView->appendLog(total > 0 ? tr("[%1/%2] %3").arg(done).arg(total).arg(what) : what);
    }
}

void MainWindow::onStageFinished(const AtomicNodeList &result)
{
    setRunning(false);
    AtomicNodeList list = result;
    if (list.workspaceRoot.isEmpty())
        list.workspaceRoot = m_workspace;
    const QString nodeId = m_restoreNodeId;
    const QString portId = m_restorePortId;
    m_restoreNodeId.clear();
    m_restorePortId.clear();

    m_document->setAtomicNodes(list);
    int ports = 0;
    for (const AtomicNode &n : list.nodes)
        ports += int(n.ports.size());
    const QString summary = tr("Stage 1 finished in %1 s: %2 nodes, %3 ports, %4 diagnostics")
                                .arg(QString::number(m_runTimer.elapsed() / 1000.0, 'f', 2))
                                .arg(list.nodes.size())
                                .arg(ports)
                                .arg(list.diagnostics.size());
    m_logView->appendLog(summary);
    statusBar()->showMessage(summary, 8000);
    if (!nodeId.isEmpty())
        selectNode(nodeId, portId);
}

void MainWindow::onStageCanceled()
{
    setRunning(false);
    m_restoreNodeId.clear();
    m_restorePortId.clear();
    m_logView->appendLog(tr("Stage 1 canceled; the previous result is kept."));
    statusBar()->showMessage(tr("Stage 1 canceled"), 5000);
}

void MainWindow::selectNode(const QString &nodeId, const QString &portId)
{
    const QModelIndex index =
        portId.isEmpty() ? m_nodeModel->nodeIndex(nodeId) : m_nodeModel->portIndex(nodeId, portId);
    if (index.isValid())
        m_nodePanel->selectSourceIndex(index);
}

void MainWindow::onNodeSelected(const QModelIndex &sourceIndex)
{
    if (m_syncingSelection)
        return;
    const Evidence evidence = m_nodeModel->evidence(sourceIndex);
    if (evidence.isValid())
        showEvidence(evidence);
}

void MainWindow::showEvidence(const Evidence &evidence)
{
    if (!m_sourceView->showEvidence(evidence))
        statusBar()->showMessage(tr("Cannot show %1").arg(evidence.file), 5000);
}

void MainWindow::onSourceLineChanged(const QString &file, int line)
{
    const QModelIndex index = m_nodeModel->indexAt(file, line);
    if (!index.isValid())
        return;
    m_syncingSelection = true;
    m_nodePanel->selectSourceIndex(index);
    m_syncingSelection = false;
}

} // namespace rosarch
