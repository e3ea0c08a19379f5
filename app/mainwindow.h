#pragma once

#include "launch/launchanalyzer.h"

#include <QMainWindow>

class QDockWidget;
class QFrame;
class QLabel;
class QMenu;
class QProgressBar;
class QToolBar;
class QToolButton;

namespace rosarch {

class ArchitectureDiffView;
class AtomicNodeModel;
class CompareController;
class RenderController;
class AtomicNodePanel;
class CorrectionController;
class CorrectionModel;
class CorrectionPanel;
class InspectorPanel;
class DiagramController;
class DiagramFocus;
class DiagramLayouter;
class DiagramPanel;
class DiagnosticModel;
class Document;
class LaunchTreeModel;
class LaunchTreePanel;
class LogView;
class NavigationController;
class ProjectController;
class SourceView;
class StageController;
class WorkspaceWatcher;
class StageRunner;
class SuggestionController;
class SuggestionModel;
class SuggestionPanel;
class ParameterPanel;
class TalkersPanel;
class Traceability;

/// The main window: wires the Document, the stage runner and the panels (atomic nodes,
/// launch tree, composed diagram, source, log), owns the menus, toolbar and status bar, and
/// remembers the session.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    /// Opens a workspace folder and its project (asking Save / Discard / Cancel first when
    /// another project has unsaved changes) and runs stages 1 to 3 on it with the project's
    /// launch options.
    void openWorkspace(const QString &path);
    /// Runs stages 1 to 3 again (F5).
    void runAllStages();
    /// Runs stage 2 alone against the current atomic nodes, with the current launch options.
    void runLaunchStage();
    /// Stores `options` (Document and settings) and runs stage 2 with them.
    void applyLaunchOptions(const LaunchOptions &options);
    /// Declares ports as expected externals in the project ("input /scan", ...) and runs the
    /// launch stage and the checks again.
    void acceptExternals(const QStringList &declarations);
    /// Opens Stages → Launch Arguments… (window-modal; OK applies the options).
    void showLaunchArgumentsDialog();
    QString workspace() const;

    /// Writes the artifacts of the current model into `folder`; false (and a dialog) on error.
    bool exportArtifactsTo(const QString &folder);
    /// Writes one NoDL description per node class of the accepted model into `folder`.
    bool exportNodlTo(const QString &folder);

    // For wiring and tests.
    Document *document() const { return m_document; }
    StageRunner *runner() const { return m_runner; }
    AtomicNodeModel *nodeModel() const { return m_nodeModel; }
    AtomicNodePanel *nodePanel() const { return m_nodePanel; }
    LaunchTreeModel *launchModel() const { return m_launchModel; }
    LaunchTreePanel *launchPanel() const { return m_launchPanel; }
    QAction *runLaunchAction() const { return m_runLaunchAction; }
    QAction *launchArgumentsAction() const { return m_launchArgumentsAction; }
    SourceView *sourceView() const { return m_sourceView; }
    DiagramPanel *diagramPanel() const { return m_diagramPanel; }
    DiagramController *diagrams() const { return m_diagrams; }
    SuggestionPanel *suggestionPanel() const { return m_suggestionPanel; }
    SuggestionController *suggestions() const { return m_suggestions; }
    QAction *suggestAction() const { return m_suggestAction; }
    LogView *logView() const { return m_logView; }
    QLabel *countsLabel() const { return m_countsLabel; }
    CompareController *compare() const { return m_compare; }
    RenderController *render() const { return m_render; }
    ProjectController *projects() const { return m_projects; }
    ArchitectureDiffView *changesView() const { return m_changesView; }
    TalkersPanel *talkersPanel() const { return m_talkersPanel; }
    ParameterPanel *parameterPanel() const { return m_parameterPanel; }
    QDockWidget *parametersDock() const { return m_parameterDock; }
    QDockWidget *talkersDock() const { return m_talkersDock; }
    CorrectionController *corrections() const { return m_correctionController; }
    CorrectionPanel *correctionPanel() const { return m_correctionPanel; }
    CorrectionModel *correctionModel() const { return m_correctionModel; }
    InspectorPanel *inspector() const { return m_inspector; }
    QDockWidget *correctionsDock() const { return m_correctionsDock; }
    QDockWidget *inspectorDock() const { return m_inspectorDock; }
    NavigationController *navigation() const { return m_navigation; }
    DiagramFocus *diagramFocus() const { return m_diagramFocus; }

protected:
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void createPanels();
    // Corrections, in mainwindowcorrections.cpp.
    void createCorrectionDocks();
    void createCorrectionController();
    void placeCorrectionDocks();
    void createCorrectionMenu();
    void createActions();
    void createMenus();
    void createStatusBar();
    void restoreSession();
    /// Whether a window of `size` gets the small layout (the Log across the bottom).
    static bool isSmallLayout(const QSize &size);
    void saveSession();
    void resetLayout();
    void takeOutDock(QDockWidget *dock);

    void openWorkspaceDialog();
    void exportArtifactsDialog();
    void updateRecentMenu();
    void openWorkspaceNow(const QString &root);
    void updateTitle();
    void updateCounts();
    /// What the empty panels say: open a workspace, reading, stopped before a result, no
    /// package here, no node classes, no launch files.
    void updatePlaceholders();
    void showError(const QString &title, const QString &text);

    void onStageStarted();
    void onStageProgressed(int done, int total, const QString &what, int stage);
    void setRunning(bool running);

    Document *m_document;
    QString m_foldersOnlyNoted; ///< the workspace the Log said is watched by folders only
    StageRunner *m_runner;
    AtomicNodeModel *m_nodeModel;
    LaunchTreeModel *m_launchModel;
    DiagnosticModel *m_diagnosticModel;
    Traceability *m_traceability = nullptr;
    StageController *m_stages = nullptr;

    AtomicNodePanel *m_nodePanel = nullptr;
    LaunchTreePanel *m_launchPanel = nullptr;
    SourceView *m_sourceView = nullptr;
    DiagramLayouter *m_diagramLayouter = nullptr; ///< the panel's layouts, off the UI thread
    DiagramPanel *m_diagramPanel = nullptr;
    DiagramController *m_diagrams = nullptr;
    SuggestionModel *m_suggestionModel = nullptr;
    SuggestionPanel *m_suggestionPanel = nullptr;
    SuggestionController *m_suggestions = nullptr;
    QDockWidget *m_suggestionDock = nullptr;
    LogView *m_logView = nullptr;
    QDockWidget *m_nodeDock = nullptr;
    QDockWidget *m_launchDock = nullptr;
    QDockWidget *m_diagramDock = nullptr;
    QDockWidget *m_sourceDock = nullptr;
    QDockWidget *m_logDock = nullptr;
    QDockWidget *m_changesDock = nullptr; ///< architecture changes; shown by a comparison
    ArchitectureDiffView *m_changesView = nullptr;
    QDockWidget *m_talkersDock = nullptr; ///< who talks on a name; shown by a click on one
    TalkersPanel *m_talkersPanel = nullptr;
    ParameterPanel *m_parameterPanel = nullptr;
    QDockWidget *m_parameterDock = nullptr; ///< the selection's parameters; a tab by the log
    CorrectionModel *m_correctionModel = nullptr;
    CorrectionPanel *m_correctionPanel = nullptr;
    InspectorPanel *m_inspector = nullptr;
    QDockWidget *m_correctionsDock = nullptr;
    QDockWidget *m_inspectorDock = nullptr;
    CorrectionController *m_correctionController = nullptr;
    CompareController *m_compare = nullptr;
    RenderController *m_render = nullptr;
    ProjectController *m_projects = nullptr;
    NavigationController *m_navigation = nullptr; ///< back and forward over the panels
    DiagramFocus *m_diagramFocus = nullptr;       ///< View → Focus Diagram
    QToolBar *m_toolBar = nullptr;

    QAction *m_openAction = nullptr;
    QAction *m_exportAction = nullptr;
    QAction *m_exportNodlAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_findAction = nullptr;
    QAction *m_nextDiagnosticAction = nullptr;
    QAction *m_previousDiagnosticAction = nullptr;
    QAction *m_runAction = nullptr;
    QAction *m_runLaunchAction = nullptr;
    QAction *m_launchArgumentsAction = nullptr;
    QAction *m_cancelAction = nullptr;
    QAction *m_suggestAction = nullptr;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_watchAction = nullptr;
    WorkspaceWatcher *m_watcher = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_aboutQtAction = nullptr;
    QMenu *m_recentMenu = nullptr;

    QLabel *m_countsLabel = nullptr;
    QFrame *m_countsSeparator = nullptr;
    QProgressBar *m_progressBar = nullptr;
    QToolButton *m_cancelButton = nullptr;

    QByteArray m_defaultState;
    bool m_closeConfirmed = false; ///< the unsaved changes were saved or discarded
    bool m_runStopped = false;     ///< the last run was canceled or failed
    QString m_lastProgressText;
};

} // namespace rosarch
