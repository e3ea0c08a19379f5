#include "app/exportcontroller.h"
#include "app/appsettings.h"
#include "app/commands/siteexport.h"
#include "app/siteexportdialog.h"
#include "app/stagecontroller.h"
#include "artifacts/artifactwriter.h"
#include "artifacts/nodlwriter.h"
#include "document/document.h"
#include "project/project.h"
#include "widgets/logview.h"

#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMainWindow>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>

namespace rosarch {

ExportController::ExportController(QMainWindow *window, Document *document,
                                   const StageController *stages, LogView *log)
    : QObject(window), m_window(window), m_document(document), m_stages(stages), m_log(log)
{
}

void ExportController::exportArtifactsDialog()
{
    AppSettings settings;
    const QString workspace = m_stages->workspace();
    QString start = settings.lastExportFolder();
    if (start.isEmpty())
        start = workspace.isEmpty() ? QDir::homePath() : QFileInfo(workspace).path();
    const QString folder =
        QFileDialog::getExistingDirectory(m_window, tr("Export Artifacts To"), start);
    if (folder.isEmpty())
        return;
    settings.setLastExportFolder(folder);
    exportArtifactsTo(folder);
}

bool ExportController::exportArtifactsTo(const QString &folder)
{
    QStringList written;
    QString error, notice;
    // The model as accepted: accepted groupings are nested composites in the CCDs, accepted
    // names resolve ports, exactly as `rosarch recover` writes it for the same decisions.
    m_document->settleAccepted(); // exactly what the views show
    if (!ArtifactWriter::writeAll(m_document->accepted(), folder, &written, &error, {}, &notice)) {
        showError(tr("Export failed"),
                  tr("The artifacts could not be written to “%1”:\n%2\n\n"
                     "Choose a folder you can write to, or free some space, and export again.")
                      .arg(QDir::toNativeSeparators(folder), error));
        m_log->appendLog(tr("Export to %1 failed: %2").arg(folder, error));
        return false;
    }
    const QString message = written.size() == 1 ? tr("Exported 1 file to %1")
                                                : tr("Exported %1 files to %2").arg(written.size());
    m_log->appendLog(message.arg(QDir::toNativeSeparators(folder)));
    if (!notice.isEmpty())
        m_log->appendLog(notice);
    m_window->statusBar()->showMessage(message.arg(QDir::toNativeSeparators(folder)), 5000);
    return true;
}

void ExportController::exportNodlDialog()
{
    const QString workspace = m_stages->workspace();
    const QString folder = QFileDialog::getExistingDirectory(
        m_window, tr("Export NoDL To"),
        workspace.isEmpty() ? QDir::homePath() : QFileInfo(workspace).path());
    if (!folder.isEmpty())
        exportNodlTo(folder);
}

bool ExportController::exportNodlTo(const QString &folder)
{
    // the node classes as accepted, as `rosarch export nodl` writes them
    m_document->settleAccepted();
    const NodlWriter::Documents nodl = NodlWriter::write(m_document->accepted().nodes);
    QString error;
    if (!NodlWriter::writeTo(nodl, folder, &error)) {
        showError(tr("Export failed"), tr("The NoDL descriptions could not be written:\n%1\n\n"
                                          "Choose a folder you can write to, and export again.")
                                           .arg(error));
        m_log->appendLog(tr("NoDL export to %1 failed: %2").arg(folder, error));
        return false;
    }
    const QString message =
        tr("Exported %n NoDL descriptions to %1", nullptr, int(nodl.files.size()))
            .arg(QDir::toNativeSeparators(folder));
    m_log->appendLog(message);
    for (const QString &line : nodl.omitted)
        m_log->appendLog(tr("NoDL: %1").arg(line));
    m_window->statusBar()->showMessage(message, 5000);
    return true;
}

void ExportController::exportSiteDialog()
{
    const QString workspace = m_stages->workspace();
    if (workspace.isEmpty()) {
        showError(tr("Export failed"), tr("Open a workspace first: the site shows its "
                                          "architecture."));
        return;
    }
    SiteExportDialog dialog(workspace, m_window);
    if (dialog.exec() != QDialog::Accepted)
        return;
    SiteOptions options = dialog.options();
    options.version = QApplication::applicationVersion();
    // The pages and their diagrams take seconds on a big workspace: a worker writes them.
    auto *job = new SiteExport(this);
    auto *progress =
        new QProgressDialog(tr("Writing the architecture site…"), tr("Cancel"), 0, 0, m_window);
    progress->setWindowModality(Qt::WindowModal);
    progress->setMinimumDuration(400);
    connect(job, &SiteExport::progressed, progress, [progress](int done, int total) {
        progress->setMaximum(total);
        progress->setValue(done);
    });
    connect(progress, &QProgressDialog::canceled, job, &SiteExport::cancel);
    connect(job, &SiteExport::finished, this,
            [this, job, progress](bool ok, const QString &message) {
                progress->reset();
                progress->deleteLater();
                job->deleteLater();
                m_log->appendLog(message);
                if (ok)
                    m_window->statusBar()->showMessage(message, 5000);
                else
                    showError(tr("Export failed"),
                              tr("The architecture site could not be written:\n%1").arg(message));
            });
    m_document->settleAccepted();
    job->start(m_document->accepted(), m_document->session()->project(), options);
}

void ExportController::showError(const QString &title, const QString &text)
{
    // Window-modal but not blocking: the caller (and an offscreen test) carries on.
    auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, m_window);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

} // namespace rosarch
