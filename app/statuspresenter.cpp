#include "app/statuspresenter.h"
#include "app/paneldocks.h"
#include "app/stagecontroller.h"
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
#include <QMainWindow>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolButton>

namespace rosarch {

StatusPresenter::StatusPresenter(QMainWindow *window, Document *document, StageRunner *runner,
                                 const StageController *stages, PanelDocks *docks,
                                 QAction *cancelAction)
    : QObject(window), m_window(window), m_document(document), m_runner(runner), m_stages(stages),
      m_docks(docks), m_cancelAction(cancelAction), m_countsLabel(new QLabel(window)),
      m_countsSeparator(new QFrame(window)), m_progressBar(new QProgressBar(window)),
      m_cancelButton(new QToolButton(window))
{
    m_countsLabel->setObjectName(QStringLiteral("countsLabel"));
    m_progressBar->setObjectName(QStringLiteral("stageProgressBar"));
    m_progressBar->setFixedWidth(220);
    m_progressBar->setMaximumHeight(16);
    m_progressBar->setTextVisible(false);
    m_cancelButton->setDefaultAction(m_cancelAction);
    m_cancelButton->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_cancelButton->setAutoRaise(true);
    // A line between the messages and the counts: a long message is cut where they begin,
    // and its last number would otherwise read as the first count's.
    m_countsSeparator->setFrameShape(QFrame::VLine);
    m_countsSeparator->setFrameShadow(QFrame::Sunken);
    m_countsLabel->setContentsMargins(4, 0, 0, 0);
    QStatusBar *bar = window->statusBar();
    bar->addPermanentWidget(m_countsSeparator);
    bar->addPermanentWidget(m_countsLabel);
    bar->addPermanentWidget(m_progressBar);
    bar->addPermanentWidget(m_cancelButton);

    connect(m_runner, &StageRunner::stageStarted, this, &StatusPresenter::onStageStarted);
    connect(m_runner, &StageRunner::stageProgressed, this, &StatusPresenter::onStageProgressed);
    connect(m_runner, &StageRunner::stageFinished, this, [this] { onStageEnded(false); });
    connect(m_runner, &StageRunner::launchStageFinished, this, [this] { onStageEnded(false); });
    connect(m_runner, &StageRunner::stageCanceled, this, [this] { onStageEnded(true); });
    connect(m_runner, &StageRunner::stageFailed, this, [this] { onStageEnded(true); });
}

RecoveryCounts StatusPresenter::updateCounts()
{
    const AtomicNodeList &list = m_document->atomicNodes();
    const RecoveryCounts counts =
        RecoveryCounts::of({list, m_document->launchDependencies(), m_document->architecture()});
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
                         count(counts.diagnostics, tr("1 diagnostic"), tr("%1 diagnostics"))};
    m_countsLabel->setText(parts.join(QStringLiteral(" · ")));
    m_countsLabel->setToolTip(tr("Stage 1: packages, atomic node classes and their ports.\n"
                                 "Stage 2: launch files found, node instances they start and "
                                 "expressions that could not be resolved statically.\n"
                                 "Stage 3: composites, one per launch-file instance."));
    updatePlaceholders();
    return counts;
}

void StatusPresenter::updatePlaceholders()
{
    const AtomicNodeList &nodes = m_document->atomicNodes();
    const LaunchDependencies &launch = m_document->launchDependencies();
    const bool noResult =
        nodes.packages.isEmpty() && nodes.nodes.isEmpty() && launch.launchFiles.isEmpty();
    const QString stopped =
        tr("The run stopped before it had a result, so nothing is known yet.\n\nRun it again "
           "with Stages → Run All.");
    QString nodesText, launchText, diagramText;
    if (m_stages->workspace().isEmpty() && m_document->workspaceRoot().isEmpty()) {
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
    m_docks->nodePanel()->setPlaceholderText(nodesText);
    m_docks->launchPanel()->setPlaceholderText(launchText);
    m_docks->diagramPanel()->setEmptyText(diagramText);
}

void StatusPresenter::setRunning(bool running)
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

void StatusPresenter::onStageStarted()
{
    m_lastProgressText.clear();
    m_progressBar->setRange(0, 0);
    setRunning(true);
}

void StatusPresenter::onStageEnded(bool stopped)
{
    m_runStopped = stopped;
    setRunning(false);
}

void StatusPresenter::onStageProgressed(int done, int total, const QString &what, int stage)
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
        m_window->statusBar()->showMessage(text);
        return;
    }
    if (!what.isEmpty() && what != m_lastProgressText) {
        m_lastProgressText = what;
        m_window->statusBar()->showMessage(what);
        m_docks->logView()->appendLog(total > 0 ? tr("[%1/%2] %3").arg(done).arg(total).arg(what)
                                                : what);
    }
}

} // namespace rosarch
