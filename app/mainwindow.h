#pragma once

#include "atomicnodelist.h"
#include "evidence.h"

#include <QElapsedTimer>
#include <QMainWindow>

class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QToolBar;
class QToolButton;

namespace rosarch {

class AtomicNodeModel;
class AtomicNodePanel;
class DiagnosticModel;
class Document;
class LogView;
class SourceView;
class StageRunner;

/// The main window: wires the Document, the stage runner and the panels (atomic nodes,
/// source, log), owns the menus, toolbar and status bar, and remembers the session.
class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    /// Opens a workspace folder and runs stage 1 on it.
    void openWorkspace(const QString &path);
    QString workspace() const { return m_workspace; }

    /// Writes the artifacts of the current model into `folder`; false (and a dialog) on error.
    bool exportArtifactsTo(const QString &folder);

    // For wiring and tests.
    Document *document() const { return m_document; }
    StageRunner *runner() const { return m_runner; }
    AtomicNodeModel *nodeModel() const { return m_nodeModel; }
    AtomicNodePanel *nodePanel() const { return m_nodePanel; }
    SourceView *sourceView() const { return m_sourceView; }
    LogView *logView() const { return m_logView; }
    QLabel *countsLabel() const { return m_countsLabel; }

protected:
    void closeEvent(QCloseEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    void createPanels();
    void createActions();
    void createMenus();
    void createStatusBar();
    void restoreSession();
    void saveSession();
    void resetLayout();

    void openWorkspaceDialog();
    void exportArtifactsDialog();
    void runStage1();
    void updateRecentMenu();
    void updateCounts();
    void showError(const QString &title, const QString &text);

    void onStageStarted(const QString &root);
    void onStageProgressed(int done, int total, const QString &what);
    void onStageFinished(const AtomicNodeList &result);
    void onStageCanceled();
    void setRunning(bool running);

    void onNodeSelected(const QModelIndex &sourceIndex);
    void onSourceLineChanged(const QString &file, int line);
    void showEvidence(const Evidence &evidence);
    void selectNode(const QString &nodeId, const QString &portId);

    Document *m_document;
    StageRunner *m_runner;
    AtomicNodeModel *m_nodeModel;
    DiagnosticModel *m_diagnosticModel;

    AtomicNodePanel *m_nodePanel = nullptr;
    SourceView *m_sourceView = nullptr;
    LogView *m_logView = nullptr;
    QDockWidget *m_nodeDock = nullptr;
    QDockWidget *m_sourceDock = nullptr;
    QDockWidget *m_logDock = nullptr;
    QToolBar *m_toolBar = nullptr;

    QAction *m_openAction = nullptr;
    QAction *m_exportAction = nullptr;
    QAction *m_quitAction = nullptr;
    QAction *m_undoAction = nullptr;
    QAction *m_redoAction = nullptr;
    QAction *m_findAction = nullptr;
    QAction *m_nextDiagnosticAction = nullptr;
    QAction *m_previousDiagnosticAction = nullptr;
    QAction *m_runAction = nullptr;
    QAction *m_cancelAction = nullptr;
    QAction *m_resetLayoutAction = nullptr;
    QAction *m_aboutAction = nullptr;
    QAction *m_aboutQtAction = nullptr;
    QMenu *m_recentMenu = nullptr;

    QLabel *m_countsLabel = nullptr;
    QProgressBar *m_progressBar = nullptr;
    QToolButton *m_cancelButton = nullptr;

    QString m_workspace;
    QByteArray m_defaultState;
    QElapsedTimer m_runTimer;
    QString m_lastProgressText;
    QString m_restoreNodeId; ///< selection to restore when the next result arrives
    QString m_restorePortId;
    bool m_syncingSelection = false; ///< the tree follows the source; do not echo back
};

} // namespace rosarch
