// The main window's status bar: the counts of what the stages found, the progress of a run
// with its cancel button, and the launch tree's placeholder while there is nothing to show.
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "pipeline/recovery.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"

#include <QAction>
#include <QFrame>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolButton>

namespace rosarch {

void MainWindow::createStatusBar()
{
    m_countsLabel = new QLabel(this);
    m_progressBar = new QProgressBar(this);
    m_progressBar->setFixedWidth(220);
    m_progressBar->setMaximumHeight(16);
    m_progressBar->setTextVisible(false);
    m_cancelButton = new QToolButton(this);
    m_cancelButton->setDefaultAction(m_cancelAction);
    m_cancelButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_cancelButton->setAutoRaise(true);
    // A line between the messages and the counts: a long message is cut where they begin,
    // and its last number would otherwise read as the first count's.
    m_countsSeparator = new QFrame(this);
    m_countsSeparator->setFrameShape(QFrame::VLine);
    m_countsSeparator->setFrameShadow(QFrame::Sunken);
    m_countsLabel->setContentsMargins(4, 0, 0, 0);
    statusBar()->addPermanentWidget(m_countsSeparator);
    statusBar()->addPermanentWidget(m_countsLabel);
    statusBar()->addPermanentWidget(m_progressBar);
    statusBar()->addPermanentWidget(m_cancelButton);
}

void MainWindow::updateCounts()
{
    const AtomicNodeList &list = m_document->atomicNodes();
    const RecoveryCounts counts =
        RecoveryCounts::of({list, m_document->launchDependencies(), m_document->architecture()});
    const qsizetype diagnostics = counts.diagnostics;
    // Explicit singular/plural: no translator is loaded for English, so "%n node(s)" would show.
    const auto count = [](qsizetype n, const QString &one, const QString &many) {
        return n == 1 ? one : many.arg(n);
    };
    QStringList parts{count(counts.packages, tr("1 package"), tr("%1 packages")),
                      count(counts.nodes, tr("1 node"), tr("%1 nodes"))};
    if (counts.plugins > 0)
        parts << count(counts.plugins, tr("1 plugin"), tr("%1 plugins"));
    parts << QStringList{count(counts.ports, tr("1 port"), tr("%1 ports")),
                         count(counts.launchFiles, tr("1 launch file"), tr("%1 launch files")),
                         count(counts.nodeInstances, tr("1 instance"), tr("%1 instances")),
                         count(counts.unresolved, tr("1 unresolved"), tr("%1 unresolved")),
                         count(counts.composites, tr("1 composite"), tr("%1 composites")),
                         count(diagnostics, tr("1 diagnostic"), tr("%1 diagnostics"))};
    m_countsLabel->setText(parts.join(QStringLiteral(" · ")));
    m_countsLabel->setToolTip(tr("Stage 1: packages, atomic node classes and their ports.\n"
                                 "Stage 2: launch files found, node instances they start and "
                                 "expressions that could not be resolved statically.\n"
                                 "Stage 3: composites, one per launch-file instance."));
    m_exportAction->setEnabled(!list.workspaceRoot.isEmpty());
    m_nextDiagnosticAction->setEnabled(diagnostics > 0);
    m_previousDiagnosticAction->setEnabled(diagnostics > 0);
    updatePlaceholders();
}

void MainWindow::updatePlaceholders()
{
    const AtomicNodeList &nodes = m_document->atomicNodes();
    const LaunchDependencies &launch = m_document->launchDependencies();
    const bool noResult =
        nodes.packages.isEmpty() && nodes.nodes.isEmpty() && launch.launchFiles.isEmpty();
    const QString stopped =
        tr("The run stopped before it had a result, so nothing is known yet.\n\nRun it again "
           "with Stages → Run All.");
    QString nodesText, launchText, diagramText;
    if (workspace().isEmpty() && m_document->workspaceRoot().isEmpty()) {
        nodesText = tr("Open a ROS 2 workspace (File → Open Workspace) to see its node classes.");
        launchText = tr("Open a ROS 2 workspace (File → Open Workspace) to see its launch tree.");
        diagramText = tr("Open a ROS 2 workspace (File → Open Workspace) to see its composed "
                         "diagrams.");
    } else if (m_runner->isRunning() && noResult) {
        nodesText = tr("Reading the workspace…");
        launchText = tr("Reading the launch files…");
        diagramText = tr("Composing the launch files…");
    } else if (m_runStopped && noResult) {
        nodesText = launchText = diagramText = stopped;
    } else if (nodes.packages.isEmpty()) {
        nodesText = tr("No ROS 2 package in this folder.\n\nrosarch finds packages by their "
                       "package.xml. Open the folder that holds them: a workspace, or its src "
                       "folder.");
        launchText = tr("No ROS 2 package in this folder, so no launch files either.");
        diagramText = tr("No ROS 2 package in this folder: there is nothing to compose.");
    } else {
        nodesText = tr("No node classes found."); // the packages show as rows
        launchText = launch.launchFiles.isEmpty()
                         ? tr("No launch files found in this workspace.\n\nStage 2 reads "
                              "*.launch.py, *.launch.xml and *.launch.yaml files and any file "
                              "holding a launch description.")
                         : tr("No launch file was analysed as a root.\n\nChoose one in Stages "
                              "→ Launch Arguments…");
        diagramText =
            launch.launchFiles.isEmpty()
                ? tr("No launch files, so nothing to compose: a composed diagram shows what a "
                     "launch file (or a program that builds several nodes) starts.")
                : tr("No composed diagram yet. Run stage 3 to compose the launch files.");
    }
    if (m_nodePanel)
        m_nodePanel->setPlaceholderText(nodesText);
    if (m_launchPanel)
        m_launchPanel->setPlaceholderText(launchText);
    if (m_diagramPanel)
        m_diagramPanel->setEmptyText(diagramText);
}

void MainWindow::setRunning(bool running)
{
    // Before a first result the counts would all read 0, as if the workspace were empty.
    const bool result = !m_document->atomicNodes().nodes.isEmpty() ||
                        !m_document->launchDependencies().launchFiles.isEmpty() ||
                        !m_document->atomicNodes().packages.isEmpty();
    m_countsLabel->setVisible(!running || result);
    m_countsSeparator->setVisible(!running || result);
    m_progressBar->setVisible(running);
    m_cancelButton->setVisible(running);
    m_cancelAction->setEnabled(running);
    updatePlaceholders();
}

void MainWindow::onStageStarted()
{
    m_lastProgressText.clear();
    m_progressBar->setRange(0, 0);
    setRunning(true);
}

void MainWindow::onStageProgressed(int done, int total, const QString &what, int stage)
{
    if (total > 0) {
        m_progressBar->setRange(0, total);
        m_progressBar->setValue(done);
    } else {
        m_progressBar->setRange(0, 0);
    }
    if (stage > 0) {
        // Per stage, with counts; the files themselves would flood the log.
        const QLocale locale;
        static const QStringList names{tr("atomic nodes"), tr("launch files"), tr("composition")};
        const QString name = names.value(stage - 1);
        QString text;
        if (total <= 0)
            text = tr("Stage %1: %2 — %3").arg(stage).arg(name, what);
        else if (stage == 3)
            text = tr("Stage %1: %2 — %3/%4 composites")
                       .arg(stage)
                       .arg(name, locale.toString(done), locale.toString(total));
        else
            text = tr("Stage %1: %2 — %3/%4 files")
                       .arg(stage)
                       .arg(name, locale.toString(done), locale.toString(total));
        m_progressBar->setToolTip(what);
        statusBar()->showMessage(text);
        return;
    }
    if (!what.isEmpty() && what != m_lastProgressText) {
        m_lastProgressText = what;
        statusBar()->showMessage(what);
        m_logView->appendLog(total > 0 ? tr("[%1/%2] %3").arg(done).arg(total).arg(what) : what);
    }
}

} // namespace rosarch
