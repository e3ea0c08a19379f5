#include "app/stagecontroller.h"
#include "app/appsettings.h"
#include "app/traceability.h"
#include "document/document.h"
#include "jobs/stallprobe.h"
#include "widgets/logview.h"

#include <utility>

namespace rosarch {

StageController::StageController(Document *document, StageRunner *runner,
                                 Traceability *traceability, LogView *log, QObject *parent)
    : QObject(parent), m_document(document), m_runner(runner), m_traceability(traceability),
      m_log(log)
{
    connect(m_runner, &StageRunner::stageStarted, this, &StageController::onStageStarted);
    connect(m_runner, &StageRunner::stageFinished, this, &StageController::onStageFinished);
    connect(m_runner, &StageRunner::launchStageFinished, this,
            &StageController::onLaunchStageFinished);
    connect(m_runner, &StageRunner::stageCanceled, this, &StageController::onStageCanceled);
    connect(m_runner, &StageRunner::stageFailed, this, &StageController::onStageFailed);
    connect(m_runner, &StageRunner::stageTimed, this, [this](int stage, qint64 ms) {
        m_log->appendLog(
            tr("%1 took %2 s").arg(stageName(stage), QString::number(ms / 1000.0, 'f', 2)));
    });
}

QString StageController::stageName(int stage)
{
    switch (stage) {
    case 1:
        return tr("Stage 1 (atomic nodes)");
    case 2:
        return tr("Stage 2 (launch files)");
    case 3:
        return tr("Stage 3 (composition)");
    default:
        return tr("Stage %1").arg(stage);
    }
}

void StageController::setWorkspace(const QString &root)
{
    if (root == m_workspace)
        return;
    m_workspace = root;
    m_log->clearLog(); // before the project loads: what it says about its file stays
    AtomicNodeList empty;
    empty.workspaceRoot = root;
    m_document->setAtomicNodes(empty);
    AppSettings settings;
    settings.selection(root, &m_restoreNodeId, &m_restorePortId);
    m_restoreLaunchId = settings.launchSelection(root);
    // The project's launch options; a project without any starts from those remembered here
    // before projects held them.
    if (m_document->session()->launchOptions() == LaunchOptions())
        m_document->session()->adoptLaunchOptions(settings.launchOptions(root));
}

void StageController::runAll()
{
    if (m_workspace.isEmpty())
        return;
    rememberSelection();
    // What is shown, to tell a re-run that found nothing new (compared off the UI thread).
    const Recovery shown =
        m_document->workspaceRoot() == m_workspace ? m_document->recovered() : Recovery{};
    m_runner->run(m_workspace, m_document->session()->launchOptions(), shown);
}

void StageController::runLaunch()
{
    // Stage 2 needs stage 1's classes of this workspace; without them run both.
    if (m_workspace.isEmpty() || m_document->workspaceRoot() != m_workspace ||
        (m_runner->isRunning() && m_runner->currentJob() == StageRunner::Job::Recovery)) {
        runAll();
        return;
    }
    rememberSelection();
    m_runner->runLaunch(m_workspace, m_document->atomicNodes(),
                        m_document->session()->launchOptions());
}

void StageController::applyLaunchOptions(const LaunchOptions &options)
{
    m_document->session()->setLaunchOptions(options);
    if (!m_workspace.isEmpty())
        AppSettings().setLaunchOptions(m_workspace, options);
    runLaunch();
}

void StageController::rememberSelection()
{
    // Kept until the next result arrives, unless a restore from the session is pending.
    if (m_restoreNodeId.isEmpty()) {
        m_restoreNodeId = m_traceability->currentNodeId();
        m_restorePortId = m_traceability->currentPortId();
    }
    if (m_restoreLaunchId.isEmpty())
        m_restoreLaunchId = m_traceability->currentLaunchId();
}

void StageController::restoreSelection()
{
    const QString nodeId = std::exchange(m_restoreNodeId, QString());
    const QString portId = std::exchange(m_restorePortId, QString());
    const QString launchId = std::exchange(m_restoreLaunchId, QString());
    if (!nodeId.isEmpty())
        m_traceability->selectNode(nodeId, portId);
    // Selected last, the launch row shows its line: it was the more specific choice.
    if (!launchId.isEmpty())
        m_traceability->selectLaunchItem(launchId);
}

void StageController::report(const QString &summary)
{
    m_log->appendLog(summary);
    Q_EMIT statusMessage(summary, 8000);
}

void StageController::onStageStarted(const QString &root, StageRunner::Job job)
{
    m_runTimer.start();
    if (job == StageRunner::Job::Recovery) {
        m_log->appendLog(
            tr("Stages 1–3 (atomic nodes, launch files, composition) started on %1").arg(root));
        Q_EMIT statusMessage(tr("Recovering atomic nodes, launch files and their composition…"), 0);
    } else {
        m_log->appendLog(tr("Stages 2–3 (launch files, composition) started on %1").arg(root));
        Q_EMIT statusMessage(tr("Reading launch files…"), 0);
    }
}

void StageController::onStageFinished(const Recovery &result)
{
    const StallScope scope("StageController::onStageFinished");
    QElapsedTimer apply;
    apply.start();
    if (m_runner->resultUnchanged() && m_document->workspaceRoot() == m_workspace) {
        // Nothing new: the views, their selection and the undo history stay as they are.
        m_restoreNodeId.clear();
        m_restorePortId.clear();
        m_restoreLaunchId.clear();
        report(tr("Stages 1–3 finished in %1 s: the result is the same as the one shown")
                   .arg(QString::number(m_runTimer.elapsed() / 1000.0, 'f', 2)));
        return;
    }
    Recovery recovery = result;
    if (recovery.nodes.workspaceRoot.isEmpty())
        recovery.nodes.workspaceRoot = m_workspace;
    m_document->setRecovery(recovery);
    m_log->appendLog(tr("Showing the result in the window took %1 s")
                         .arg(QString::number(apply.elapsed() / 1000.0, 'f', 2)));
    const RecoveryCounts counts = RecoveryCounts::of(
        {m_document->atomicNodes(), m_document->launchDependencies(), m_document->architecture()});
    report(tr("Stages 1–3 finished in %1 s: %2 nodes, %3 ports, %4 launch files, %5 node "
              "instances, %6 composites, %7 diagnostics")
               .arg(QString::number(m_runTimer.elapsed() / 1000.0, 'f', 2))
               .arg(counts.nodes)
               .arg(counts.ports)
               .arg(counts.launchFiles)
               .arg(counts.nodeInstances)
               .arg(counts.composites)
               .arg(counts.diagnostics));
    restoreSelection();
}

void StageController::onLaunchStageFinished(const LaunchDependencies &result,
                                            const Architecture &architecture)
{
    QElapsedTimer apply;
    apply.start();
    m_document->setLaunchDependencies(result, architecture);
    m_log->appendLog(tr("Showing the result in the window took %1 s")
                         .arg(QString::number(apply.elapsed() / 1000.0, 'f', 2)));
    report(tr("Stages 2–3 finished in %1 s: %2 launch files, %3 launch-file instances, %4 node "
              "instances, %5 composites, %6 diagnostics")
               .arg(QString::number(m_runTimer.elapsed() / 1000.0, 'f', 2))
               .arg(result.launchFiles.size())
               .arg(result.instances.size())
               .arg(result.nodes.size())
               .arg(architecture.composites.size())
               .arg(result.diagnostics.size() + architecture.diagnostics.size()));
    m_restoreNodeId.clear(); // the atomic tree was not rebuilt; its selection stands
    m_restorePortId.clear();
    restoreSelection();
}

void StageController::onStageCanceled(StageRunner::Job job)
{
    m_restoreNodeId.clear();
    m_restorePortId.clear();
    m_restoreLaunchId.clear();
    const QString what = job == StageRunner::Job::Recovery ? tr("Stages 1–3") : tr("Stages 2–3");
    m_log->appendLog(tr("%1 canceled; the previous result is kept.").arg(what));
    Q_EMIT statusMessage(tr("%1 canceled").arg(what), 5000);
}

void StageController::onStageFailed(StageRunner::Job job, const QString &message)
{
    m_restoreNodeId.clear();
    m_restorePortId.clear();
    m_restoreLaunchId.clear();
    const QString what = job == StageRunner::Job::Recovery ? tr("Stages 1–3") : tr("Stages 2–3");
    m_log->appendLog(
        tr("%1 stopped without a result; the previous result is kept. %2").arg(what, message));
    Q_EMIT statusMessage(tr("%1 stopped: the analysis worker failed (see the log)").arg(what), 0);
}

} // namespace rosarch
