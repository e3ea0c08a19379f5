#include "app/rendercontroller.h"
#include "app/appsettings.h"
#include "artifacts/artifactwriter.h"
#include "document/document.h"
#include "plantuml/plantumlrenderer.h"
#include "widgets/logview.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QProcess>

namespace rosarch {

RenderController::RenderController(Document *document, LogView *log, QWidget *window)
    : QObject(window), m_document(document), m_log(log), m_window(window)
{
    m_renderAction = new QAction(tr("Export and &Render with PlantUML…"), this);
    m_renderAction->setStatusTip(
        tr("Write the artifacts and render every ACD and CCD to SVG with PlantUML (needs Java "
           "and a PlantUML jar)"));
    connect(m_renderAction, &QAction::triggered, this, &RenderController::chooseFolder);
    m_jarAction = new QAction(tr("PlantUML &Jar…"), this);
    m_jarAction->setStatusTip(tr("Choose the PlantUML jar used for rendering"));
    connect(m_jarAction, &QAction::triggered, this, &RenderController::chooseJar);
}

RenderController::~RenderController()
{
    if (m_process) {
        m_process->disconnect(this);
        m_process->kill();
        m_process->waitForFinished(3000);
    }
}

bool RenderController::isRendering() const
{
    return m_process && m_process->state() != QProcess::NotRunning;
}

void RenderController::showError(const QString &title, const QString &text)
{
    // Window-modal but not blocking, like the main window's own errors.
    auto *box = new QMessageBox(QMessageBox::Warning, title, text, QMessageBox::Ok, m_window);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
}

bool RenderController::chooseJar()
{
    AppSettings settings;
    const QString jar = QFileDialog::getOpenFileName(m_window, tr("Choose the PlantUML Jar"),
                                                     QFileInfo(settings.plantUmlJar()).path(),
                                                     tr("Java archives (*.jar)"));
    if (jar.isEmpty())
        return false;
    settings.setPlantUmlJar(jar);
    m_log->appendLog(tr("PlantUML jar set to %1").arg(QDir::toNativeSeparators(jar)));
    return true;
}

void RenderController::chooseFolder()
{
    AppSettings settings;
    QString start = settings.lastExportFolder();
    if (start.isEmpty())
        start = QFileInfo(m_document->workspaceRoot()).path();
    const QString folder =
        QFileDialog::getExistingDirectory(m_window, tr("Export and Render To"), start);
    if (folder.isEmpty())
        return;
    settings.setLastExportFolder(folder);
    exportAndRender(folder);
}

bool RenderController::exportAndRender(const QString &folder)
{
    const QString configured = AppSettings().plantUmlJar();
    const QString jar = PlantUmlRenderer::findJar(configured);
    const QString java = PlantUmlRenderer::findJava();
    if (java.isEmpty()) {
        showError(tr("Java not found"),
                  tr("Rendering with PlantUML needs a Java runtime. Install one (on Debian: "
                     "apt install default-jre-headless) or set JAVA_HOME, then render again."));
        return false;
    }
    if (!configured.isEmpty() && !QFileInfo(configured).isFile()) {
        showError(tr("PlantUML jar not found"),
                  tr("The PlantUML jar chosen in File › PlantUML Jar… is no longer there:\n%1\n\n"
                     "Choose it again, then render again.")
                      .arg(QDir::toNativeSeparators(configured)));
        return false;
    }
    if (jar.isEmpty()) {
        showError(tr("PlantUML jar not found"),
                  tr("Rendering needs plantuml.jar (from plantuml.com, or "
                     "scripts/fetch-plantuml.sh in rosarch's sources). Choose it with File › "
                     "PlantUML Jar…, or set ROSARCH_PLANTUML_JAR, then render again."));
        return false;
    }
    QStringList written;
    QString error;
    m_document->settleAccepted(); // exactly what the views show
    if (!ArtifactWriter::writeAll(m_document->accepted(), folder, &written, &error)) {
        showError(tr("Export failed"),
                  tr("The artifacts could not be written to “%1”:\n%2\n\nChoose a folder you "
                     "can write to, or free some space, and try again.")
                      .arg(QDir::toNativeSeparators(folder), error));
        return false;
    }
    QStringList diagrams;
    for (const QString &file : std::as_const(written))
        if (file.endsWith(QLatin1String(".puml")))
            diagrams << file;
    m_pictures.clear();
    for (const QString &d : std::as_const(diagrams))
        m_pictures << PlantUmlRenderer::outputOf(d, QStringLiteral("svg"));
    if (m_process) { // a newer render replaces one still running
        m_process->disconnect(this);
        m_process->kill();
        m_process->waitForFinished(3000);
        m_process->deleteLater();
    }
    m_process = new QProcess(this);
    m_process->setProcessChannelMode(QProcess::MergedChannels);
    connect(m_process, &QProcess::finished, this,
            [this, folder, count = diagrams.size()](int code, QProcess::ExitStatus exit) {
                const QString output = QString::fromLocal8Bit(m_process->readAll()).trimmed();
                const bool ok = exit == QProcess::NormalExit && code == 0;
                const QString message =
                    ok ? tr("Rendered %1 diagrams to SVG in %2")
                             .arg(count)
                             .arg(QDir::toNativeSeparators(folder))
                       : tr("PlantUML failed (exit code %1): %2").arg(code).arg(output);
                m_log->appendLog(message);
                Q_EMIT status(message);
                if (!ok)
                    showError(tr("Rendering failed"), message);
                Q_EMIT rendered(ok, message, ok ? m_pictures : QStringList());
            });
    connect(m_process, &QProcess::errorOccurred, this, [this](QProcess::ProcessError e) {
        if (e != QProcess::FailedToStart)
            return;
        const QString message = tr("Java could not be started: %1").arg(m_process->errorString());
        m_log->appendLog(message);
        Q_EMIT rendered(false, message, {});
    });
    m_process->start(java, PlantUmlRenderer::arguments(jar, QStringLiteral("svg"), diagrams));
    const QString message = tr("Rendering %1 diagrams with PlantUML…").arg(diagrams.size());
    m_log->appendLog(message);
    Q_EMIT status(message);
    return true;
}

} // namespace rosarch
