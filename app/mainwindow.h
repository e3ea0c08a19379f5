#pragma once

#include "launch/launchanalyzer.h"

#include <QMainWindow>

namespace rosarch {

class AtomicNodeModel;
class CompareController;
class CorrectionController;
class CorrectionModel;
class DiagnosticModel;
class DiagramController;
class Document;
class ExportController;
class LaunchTreeModel;
class MainMenus;
class NavigationController;
class PanelDocks;
class ProjectController;
class RenderController;
class StageController;
class StageRunner;
class StatusPresenter;
class SuggestionController;
class SuggestionModel;
class Traceability;
class WorkspaceWatcher;

/// The main window: makes the Document, the stage runner, the item models, the panels and
/// the controllers and wires them together; opens workspaces and runs the stages.
/// The panels and their docks are PanelDocks', the menus MainMenus', the status bar
/// StatusPresenter's, the exports ExportController's. Tests reach the parts through the object
/// tree (findChild).
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

protected:
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void createControllers();
    void createWatcher();
    void saveSession();

    void openWorkspaceDialog();
    void openWorkspaceNow(const QString &root);
    void updateTitle();
    void updateCounts();
    void showError(const QString &title, const QString &text);

    Document *m_document;
    StageRunner *m_runner;
    AtomicNodeModel *m_nodeModel;
    LaunchTreeModel *m_launchModel;
    DiagnosticModel *m_diagnosticModel;
    SuggestionModel *m_suggestionModel;
    CorrectionModel *m_correctionModel;
    PanelDocks *m_docks;
    Traceability *m_traceability = nullptr;
    StageController *m_stages = nullptr;
    WorkspaceWatcher *m_watcher = nullptr;
    QString m_foldersOnlyNoted; ///< the workspace the Log said is watched by folders only
    DiagramController *m_diagrams = nullptr;
    SuggestionController *m_suggestions = nullptr;
    CompareController *m_compare = nullptr;
    RenderController *m_render = nullptr;
    CorrectionController *m_corrections = nullptr;
    ProjectController *m_projects = nullptr;
    NavigationController *m_navigation = nullptr; ///< back and forward over the panels
    ExportController *m_exports = nullptr;
    MainMenus *m_menus = nullptr;
    StatusPresenter *m_status = nullptr;
    bool m_closeConfirmed = false; ///< the unsaved changes were saved or discarded
};

} // namespace rosarch
