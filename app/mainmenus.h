#pragma once

#include <QObject>

class QAction;
class QMainWindow;
class QMenu;

namespace rosarch {

class CompareController;
class CorrectionController;
class DiagramController;
class Document;
class NavigationController;
class PanelDocks;
class ProjectController;
class RenderController;
class StageRunner;
class SuggestionController;
class WorkspaceWatcher;

/// The main window's actions, its menus and its toolbar. Each action has an objectName (the
/// tests find it by that name); the actions that act on the window say so by a signal.
class MainMenus : public QObject
{
    Q_OBJECT
public:
    /// What the menus hold actions of.
    struct Parts
    {
        Document *document = nullptr;
        StageRunner *runner = nullptr;
        PanelDocks *docks = nullptr;
        WorkspaceWatcher *watcher = nullptr;
        ProjectController *projects = nullptr;
        NavigationController *navigation = nullptr;
        DiagramController *diagrams = nullptr;
        RenderController *render = nullptr;
        CompareController *compare = nullptr;
        SuggestionController *suggestions = nullptr;
        CorrectionController *corrections = nullptr;
    };

    /// Makes the actions and fills the menu bar and the toolbar of `window`.
    MainMenus(QMainWindow *window, const Parts &parts);

    /// Stages → Cancel Stage, also the status bar's cancel button.
    QAction *cancelAction() const { return m_cancelAction; }
    /// Enables what needs a result: export once a workspace was read, the finding steps when
    /// there are findings.
    void enableForResult(bool hasWorkspace, qsizetype diagnostics);

signals:
    void openWorkspaceRequested();
    /// A workspace of File → Open Recent.
    void workspaceRequested(const QString &path);
    void exportArtifactsRequested();
    void exportNodlRequested();
    void exportSiteRequested();
    void runAllRequested();
    void runLaunchRequested();
    void launchArgumentsRequested();

private:
    void createActions();
    void createFileMenu();
    void createEditMenu();
    void createToolBar();
    void createViewMenu();
    void createModelMenu();
    void createStagesMenu();
    void updateRecentMenu();
    QAction *addAction(const QString &text, const QString &name);

    QMainWindow *m_window;
    Parts m_parts;
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
    QAction *m_watchAction = nullptr;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_aboutQtAction = nullptr;
    QMenu *m_recentMenu = nullptr;
};

} // namespace rosarch
