#include "app/comparecontroller.h"
#include "diff/gitrevision.h"
#include "document/document.h"
#include "pipeline/recovery.h"
#include "widgets/architecturediffview.h"
#include "widgets/logview.h"

#include <QAction>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QTemporaryDir>

namespace rosarch {

CompareController::CompareController(Document *document, ArchitectureDiffView *view,
                                     QDockWidget *dock, LogView *log, QWidget *window)
    : QObject(window), m_document(document), m_view(view), m_dock(dock), m_log(log),
      m_window(window)
{
    m_folderAction = new QAction(tr("Compare Architecture with &Folder…"), this);
    m_folderAction->setStatusTip(
        tr("Show what changed against an earlier recovery: a folder rosarch exported or "
           "`rosarch recover` wrote, or another workspace"));
    connect(m_folderAction, &QAction::triggered, this, &CompareController::chooseFolder);
    m_revisionAction = new QAction(tr("Compare Architecture with &Git Revision…"), this);
    m_revisionAction->setStatusTip(
        tr("Show what changed against the open workspace at a git revision (a branch, a tag, "
           "HEAD~1)"));
    connect(m_revisionAction, &QAction::triggered, this, &CompareController::askRevision);
    connect(&m_jobs, &JobRunner::failed, this, [this](const QString &message) {
        m_view->setMessage(tr("The comparison failed: %1").arg(message));
        Q_EMIT finished();
    });
}

void CompareController::chooseFolder()
{
    const QString folder = QFileDialog::getExistingDirectory(
        m_window, tr("Compare with an Artifact Folder or a Workspace"),
        QFileInfo(m_document->workspaceRoot()).path());
    if (!folder.isEmpty())
        compareWithFolder(folder);
}

void CompareController::askRevision()
{
    bool ok = false;
    const QString rev =
        QInputDialog::getText(
            m_window, tr("Compare with Git Revision"),
            tr("Revision of %1 to compare the current model with (a branch, a tag, a commit, "
               "HEAD~1):")
                .arg(QDir::toNativeSeparators(m_document->workspaceRoot())),
            QLineEdit::Normal, QStringLiteral("HEAD"), &ok)
            .trimmed();
    if (ok && !rev.isEmpty())
        compareWithRevision(rev);
}

void CompareController::compareWithFolder(const QString &folder)
{
    start(QDir::toNativeSeparators(folder), [folder](const JobControl &control) {
        Other other;
        if (QFileInfo::exists(QDir(folder).filePath(QStringLiteral("atomic_nodes.json")))) {
            if (!ArchitectureSnapshot::load(folder, &other.before, &other.error))
                return other;
        } else {
            control.progress(0, 0, QStringLiteral("Recovering %1").arg(folder));
            other.before =
                ArchitectureSnapshot::of(recoverWorkspace(folder, {}, control.stageControl()));
        }
        return other;
    });
}

void CompareController::compareWithRevision(const QString &revision)
{
    const QString workspace = m_document->workspaceRoot();
    start(tr("revision %1").arg(revision), [workspace, revision](const JobControl &control) {
        Other other;
        QTemporaryDir dir;
        if (!dir.isValid()) {
            other.error = QStringLiteral("Cannot create a temporary folder.");
            return other;
        }
        control.progress(0, 0, QStringLiteral("Reading revision %1").arg(revision));
        if (!GitRevision::checkout(workspace, revision, dir.path(), &other.error))
            return other;
        control.progress(0, 0, QStringLiteral("Recovering revision %1").arg(revision));
        other.before =
            ArchitectureSnapshot::of(recoverWorkspace(dir.path(), {}, control.stageControl()));
        return other;
    });
}

void CompareController::start(const QString &label,
                              std::function<Other(const JobControl &)> readOther)
{
    if (m_document->workspaceRoot().isEmpty()) {
        m_view->setMessage(tr("Open a workspace and run the stages first."));
        m_dock->show();
        Q_EMIT finished();
        return;
    }
    m_dock->show();
    m_dock->raise();
    m_view->setMessage(tr("Comparing with %1…").arg(label));
    // The current side is the model as shown, with the accepted decisions; it is copied
    // here and turned into a snapshot on the worker with the other side.
    m_document->settleAccepted(); // exactly what the views show
    const Recovery current = m_document->accepted();
    m_jobs.start<Other>(
        [current, readOther](const JobControl &control) {
            Other other = readOther(control);
            if (other.error.isEmpty() && !control.isCanceled())
                other.after = ArchitectureSnapshot::of(current);
            return other;
        },
        [this, label](Other other, bool canceled) {
            if (canceled) {
                m_view->setMessage(tr("The comparison with %1 was canceled.").arg(label));
            } else if (!other.error.isEmpty()) {
                m_view->setMessage(tr("Cannot compare with %1: %2").arg(label, other.error));
                m_log->appendLog(tr("Comparing with %1 failed: %2").arg(label, other.error));
            } else {
                m_changes = ArchitectureDiff::compare(other.before, other.after);
                m_view->setChanges(m_changes, label, tr("the current model"));
                m_log->appendLog(m_view->summary());
            }
            Q_EMIT finished();
        });
}

} // namespace rosarch
