#include "app/projectcontroller.h"
#include "app/appsettings.h"
#include "document/document.h"
#include "project/project.h"
#include "widgets/logview.h"

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QLocale>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QStandardPaths>

namespace rosarch {

namespace {
QString native(const QString &path)
{
    return QDir::toNativeSeparators(path);
}
} // namespace

ProjectController::ProjectController(Document *document, LogView *log, QWidget *window)
    : QObject(window), m_document(document), m_log(log), m_window(window),
      m_newAction(new QAction(tr("&New Project"), this)),
      m_openAction(new QAction(tr("Open &Project…"), this)),
      m_saveAction(new QAction(tr("&Save Project"), this)),
      m_saveAsAction(new QAction(tr("Save Project &As…"), this)),
      m_recentMenu(new QMenu(tr("Recent Pro&jects"), window))
{
    m_chooseFile = [this](const QString &title, const QString &start, bool forSaving) {
        const QString filter = tr("rosarch projects (*.project.json);;JSON files (*.json);;All "
                                  "files (*)");
        return forSaving ? QFileDialog::getSaveFileName(m_window, title, start, filter)
                         : QFileDialog::getOpenFileName(m_window, title, start, filter);
    };
    m_newAction->setShortcut(QKeySequence::New);
    m_newAction->setStatusTip(tr("Start an empty project (no decisions, no corrections, the "
                                 "default launch options) on the open workspace"));
    connect(m_newAction, &QAction::triggered, this, &ProjectController::newProject);
    m_openAction->setShortcut(QKeySequence(tr("Ctrl+Shift+O")));
    m_openAction->setStatusTip(tr("Open a rosarch project file and the workspace it belongs to"));
    connect(m_openAction, &QAction::triggered, this, [this] {
        const QString current = m_document->session()->projectPath();
        const QString start = !current.isEmpty()                      ? QFileInfo(current).path()
                              : m_document->workspaceRoot().isEmpty() ? QDir::homePath()
                                                                      : m_document->workspaceRoot();
        const QString file = m_chooseFile(tr("Open Project"), start, false);
        if (!file.isEmpty())
            openProject(file);
    });
    m_saveAction->setShortcut(QKeySequence::Save);
    m_saveAction->setStatusTip(tr("Write the launch options, decisions and corrections to the "
                                  "project file (by default rosarch.project.json in the "
                                  "workspace)"));
    connect(m_saveAction, &QAction::triggered, this, &ProjectController::save);
    m_saveAsAction->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    m_saveAsAction->setStatusTip(tr("Write the project to another file"));
    connect(m_saveAsAction, &QAction::triggered, this, &ProjectController::saveAs);
    connect(m_recentMenu, &QMenu::aboutToShow, this, &ProjectController::updateRecentMenu);

    const auto update = [this] {
        const bool open = !m_document->workspaceRoot().isEmpty();
        m_saveAction->setEnabled(open);
        m_saveAsAction->setEnabled(open);
    };
    connect(m_document, &Document::changed, this, update);
    update();
    connect(m_document->session(), &ProjectSession::loadFailed, this,
            [this](const QString &message) {
                m_log->appendLog(tr("The project file could not be read: %1").arg(message));
                showError(
                    tr("Cannot read the project"),
                    tr("%1\n\nrosarch opened the workspace with an empty project. Saving writes a "
                       "new project file; the unreadable one stays where it was kept.")
                        .arg(message));
            });
}

QString ProjectController::defaultTarget() const
{
    const QString root = m_document->workspaceRoot();
    const QString current = m_document->session()->projectPath();
    // A project kept under the application data moves into the workspace on its first save.
    if (current.isEmpty() || current == ProjectFile::appDataPath(root))
        return ProjectFile::defaultPath(root);
    return current;
}

void ProjectController::maybeSave(const std::function<void()> &proceed)
{
    if (!m_document->session()->isModified()) {
        proceed();
        return;
    }
    // Where Save writes, not where the project is kept now: a project kept under the
    // application data moves into the workspace on its first save.
    const QString name = m_document->session()->isUntitled()
                             ? tr("the new project")
                             : QStringLiteral("“%1”").arg(native(defaultTarget()));
    auto *box =
        new QMessageBox(QMessageBox::Warning, tr("Unsaved changes"),
                        tr("The project of “%1” has changes that are not saved.")
                            .arg(QFileInfo(m_document->workspaceRoot()).fileName()),
                        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, m_window);
    box->setObjectName(QStringLiteral("unsavedChangesBox"));
    box->setInformativeText(
        tr("Save them to %1, discard them, or cancel and stay with this project?").arg(name));
    box->setDefaultButton(QMessageBox::Save);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, proceed] {
        const QMessageBox::StandardButton answer = box->standardButton(box->clickedButton());
        if (answer == QMessageBox::Save) {
            if (save())
                proceed();
        } else if (answer == QMessageBox::Discard) {
            m_document->session()->discardChanges();
            proceed();
        }
    });
    box->open();
}

void ProjectController::projectOpened()
{
    const QString file = m_document->session()->projectPath();
    if (QFileInfo::exists(file) && file != ProjectFile::appDataPath(m_document->workspaceRoot()))
        AppSettings().addRecentProject(file);
    const QString side = m_document->session()->autosaveFile();
    if (side.isEmpty() || !QFileInfo::exists(side))
        return;
    const QDateTime when = QFileInfo(side).lastModified();
    auto *box = new QMessageBox(
        QMessageBox::Question, tr("Recover unsaved changes?"),
        tr("rosarch did not close normally while the project of “%1” had unsaved changes. They "
           "were kept on %2.")
            .arg(QFileInfo(m_document->workspaceRoot()).fileName(),
                 QLocale().toString(when, QLocale::LongFormat)),
        QMessageBox::Yes | QMessageBox::Discard, m_window);
    box->setObjectName(QStringLiteral("recoverAutosaveBox"));
    box->button(QMessageBox::Yes)->setText(tr("&Recover"));
    const QString saved = m_document->session()->projectPath();
    box->setInformativeText(
        QFileInfo::exists(saved)
            ? tr("Recover them (the project shows as modified until you save it), or discard "
                 "them and keep the project as saved in %1?")
                  .arg(native(saved))
            : tr("Recover them (the project shows as modified until you save it), or discard "
                 "them (the workspace has no saved project yet)?"));
    box->setDetailedText(tr("Autosave file: %1").arg(native(side)));
    box->setDefaultButton(QMessageBox::Yes);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, side] {
        if (box->standardButton(box->clickedButton()) != QMessageBox::Yes) {
            m_document->session()->discardAutosave();
            m_log->appendLog(tr("Discarded the autosaved changes %1").arg(native(side)));
            return;
        }
        const LaunchOptions before = m_document->session()->launchOptions();
        QString error;
        if (!m_document->session()->recoverAutosave(&error)) {
            m_log->appendLog(tr("The autosaved changes could not be recovered: %1").arg(error));
            showError(tr("Cannot recover the changes"),
                      tr("%1\n\nThe autosave file was left where it is.").arg(error));
            return;
        }
        m_log->appendLog(tr("Recovered the unsaved changes from %1").arg(native(side)));
        Q_EMIT statusMessage(tr("Recovered the unsaved changes"), 5000);
        if (m_document->session()->launchOptions() != before)
            Q_EMIT launchOptionsReplaced();
    });
    box->open();
}

bool ProjectController::save()
{
    if (m_document->workspaceRoot().isEmpty())
        return false;
    if (m_document->session()->isUntitled())
        return saveAs();
    const QString target = defaultTarget();
    if (saveTo(target))
        return true;
    // Not writable (a read-only checkout, a full disk): somewhere else, then.
    return saveAs();
}

bool ProjectController::saveAs()
{
    if (m_document->workspaceRoot().isEmpty())
        return false;
    const QString file = m_chooseFile(tr("Save Project As"), defaultTarget(), true);
    return !file.isEmpty() && saveTo(file);
}

bool ProjectController::saveTo(const QString &file)
{
    const QString absolute = QFileInfo(file).absoluteFilePath();
    if (!m_document->session()->saveAs(absolute)) {
        // saveFailed has logged why
        Q_EMIT statusMessage(tr("The project could not be saved to %1").arg(native(absolute)), 0);
        return false;
    }
    AppSettings().addRecentProject(absolute);
    m_log->appendLog(tr("Saved the project to %1").arg(native(absolute)));
    Q_EMIT statusMessage(tr("Saved %1").arg(native(absolute)), 5000);
    return true;
}

bool ProjectController::openProject(const QString &file)
{
    Project project;
    QString error;
    if (!QFileInfo::exists(file)) {
        AppSettings().removeRecentProject(file);
        showError(tr("Cannot open project"),
                  tr("The project file “%1” does not exist.").arg(native(file)));
        return false;
    }
    if (!ProjectFile::read(file, &project, &error)) {
        m_log->appendLog(tr("The project file could not be read: %1").arg(error));
        showError(tr("Cannot open project"),
                  tr("%1\n\nThe file was not opened and is left as it is.").arg(error));
        return false;
    }
    const QString workspace = ProjectFile::workspaceOf(file, project);
    if (!QFileInfo(workspace).isDir()) {
        showError(tr("Cannot open project"),
                  tr("The workspace of the project “%1” is not there: %2.\n\nMove the project "
                     "file into its workspace, or open the workspace and save the project "
                     "again.")
                      .arg(native(file), native(workspace)));
        return false;
    }
    const QString absolute = QFileInfo(file).absoluteFilePath();
    const QString root = QFileInfo(workspace).canonicalFilePath();
    maybeSave([this, absolute, root] {
        AppSettings().addRecentProject(absolute);
        if (root != m_document->workspaceRoot()) {
            m_document->session()->setProjectFile(root, absolute); // read when the workspace opens
            Q_EMIT workspaceRequested(root);
            return;
        }
        const LaunchOptions before = m_document->session()->launchOptions();
        m_document->session()->setProjectFile(root, absolute);
        m_log->appendLog(tr("Opened the project %1").arg(native(absolute)));
        projectOpened();
        if (m_document->session()->launchOptions() != before)
            Q_EMIT launchOptionsReplaced();
    });
    return true;
}

void ProjectController::newProject()
{
    const QString root = m_document->workspaceRoot();
    if (root.isEmpty()) {
        showError(tr("No workspace"), tr("A project belongs to a workspace: open one with File → "
                                         "Open Workspace, then start a new project on it."));
        return;
    }
    maybeSave([this, root] {
        const LaunchOptions before = m_document->session()->launchOptions();
        m_document->session()->setProjectFile(root, {});
        m_log->appendLog(tr("Started a new project on %1").arg(native(root)));
        if (m_document->session()->launchOptions() != before)
            Q_EMIT launchOptionsReplaced();
    });
}

void ProjectController::updateRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = AppSettings().recentProjects();
    if (recent.isEmpty()) {
        m_recentMenu->addAction(tr("No recent projects"))->setEnabled(false);
        return;
    }
    for (int i = 0; i < recent.size(); ++i) {
        const QString &file = recent[i];
        const QString label = tr("&%1 %2")
                                  .arg(i + 1 < 10 ? QString::number(i + 1) : QStringLiteral("1&0"))
                                  .arg(native(file));
        QAction *action = m_recentMenu->addAction(label);
        action->setData(file);
        if (!QFileInfo::exists(file)) {
            action->setEnabled(false);
            action->setToolTip(tr("Not found"));
            continue;
        }
        connect(action, &QAction::triggered, this, [this, file] { openProject(file); });
    }
    m_recentMenu->addSeparator();
    connect(m_recentMenu->addAction(tr("&Clear Menu")), &QAction::triggered, this,
            [] { AppSettings().clearRecentProjects(); });
}

void ProjectController::showError(const QString &title, const QString &text)
{
    auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, m_window);
    box->setObjectName(QStringLiteral("projectErrorBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace rosarch
