#pragma once

#include <QObject>
#include <QString>

#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace rosarch {

class Document;
class LogView;

/// The project file as a desktop user expects it: File → New Project, Open Project…, Save
/// Project, Save Project As…, Recent Projects; Save / Discard / Cancel before unsaved changes
/// are replaced; the offer to recover what an autosave kept when rosarch did not close
/// normally. Dialogs are window-modal and do not block (tests answer them); the file chooser
/// can be replaced.
class ProjectController : public QObject
{
    Q_OBJECT
public:
    /// Asks for a file: `title`, the file to start from, whether it is for saving.
    using FileChooser =
        std::function<QString(const QString &title, const QString &start, bool forSaving)>;

    ProjectController(Document *document, LogView *log, QWidget *window);

    QAction *newAction() const { return m_newAction; }
    QAction *openAction() const { return m_openAction; }
    QAction *saveAction() const { return m_saveAction; }
    QAction *saveAsAction() const { return m_saveAsAction; }
    QMenu *recentMenu() const { return m_recentMenu; }
    void setFileChooser(FileChooser chooser) { m_chooseFile = std::move(chooser); }

    /// Calls `proceed` at once when the project is not modified; else asks Save / Discard /
    /// Cancel and calls it after a successful save or a discard (never on Cancel).
    void maybeSave(const std::function<void()> &proceed);
    /// A workspace and its project were opened: remembers the project among the recent ones
    /// and offers to recover its autosave side file if one was left behind.
    void projectOpened();
    /// Save Project: to the project's file, or to `<workspace>/rosarch.project.json` for a
    /// project kept under the application data; asks where (Save As) for a new project or when
    /// that cannot be written. False when nothing was saved.
    bool save();
    /// Save Project As…: asks for a file; false when canceled or writing failed.
    bool saveAs();
    /// Saves to `file` (no dialog); false (and a message) when writing failed.
    bool saveTo(const QString &file);
    /// Opens a project file and its workspace (after Save / Discard / Cancel); false (and a
    /// dialog) when the file cannot be read or its workspace does not exist.
    bool openProject(const QString &file);
    /// New Project: an empty project of the current workspace that Save asks a file for.
    void newProject();
    /// Rebuilds the Recent Projects menu (missing files greyed).
    void updateRecentMenu();

Q_SIGNALS:
    /// A project of another workspace was opened: the window opens that workspace (no
    /// further question: its changes were saved or discarded).
    void workspaceRequested(const QString &root);
    /// The project's launch options changed (another project, a recovered one): run stage 2.
    void launchOptionsReplaced();
    void statusMessage(const QString &text, int timeout);

private:
    void showError(const QString &title, const QString &text);
    QString defaultTarget() const;

    Document *m_document;
    LogView *m_log;
    QWidget *m_window;
    FileChooser m_chooseFile;
    QAction *m_newAction;
    QAction *m_openAction;
    QAction *m_saveAction;
    QAction *m_saveAsAction;
    QMenu *m_recentMenu;
};

} // namespace rosarch
