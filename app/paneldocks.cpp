#include "app/paneldocks.h"
#include "app/appsettings.h"
#include "app/diagramfocus.h"
#include "diagram/diagramlayouter.h"
#include "widgets/architecturediffview.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/correctionpanel.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/inspectorpanel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/parameterpanel.h"
#include "widgets/sourceview.h"
#include "widgets/suggestionpanel.h"
#include "widgets/talkerspanel.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QDockWidget>
#include <QMainWindow>
#include <QPlainTextEdit>
#include <QScreen>
#include <QToolBar>

#include <algorithm>

namespace rosarch {

PanelDocks::PanelDocks(QMainWindow *window) : QObject(window), m_window(window)
{
    m_nodePanel = new AtomicNodePanel(window);
    m_launchPanel = new LaunchTreePanel(window);
    m_diagramLayouter = new DiagramLayouter(window);
    m_diagramPanel = new DiagramPanel(m_diagramLayouter, window);
    m_sourceView = new SourceView(window);
    m_logView = new LogView(window);
    // Folders dropped anywhere open a workspace; the text views must not swallow them.
    m_sourceView->editor()->setAcceptDrops(false);
    m_sourceView->editor()->viewport()->setAcceptDrops(false);
    m_logView->logEdit()->setAcceptDrops(false);
    m_logView->logEdit()->viewport()->setAcceptDrops(false);

    addDock(m_nodePanel, tr("Atomic nodes"), QStringLiteral("atomicNodesDock"));
    addDock(m_launchPanel, tr("Launch tree"), QStringLiteral("launchTreeDock"));
    addDock(m_diagramPanel, tr("Composed diagram"), QStringLiteral("diagramDock"));
    addDock(m_sourceView, tr("Source"), QStringLiteral("sourceDock"));
    QDockWidget *logDock = addDock(m_logView, tr("Log"), QStringLiteral("logDock"));
    // The title (and its tab) counts the findings; the View menu keeps saying "Log".
    connect(m_logView, &LogView::titleChanged, logDock, [logDock](const QString &title) {
        logDock->setWindowTitle(title);
        logDock->toggleViewAction()->setText(tr("Log"));
    });
    m_suggestionPanel = new SuggestionPanel(window);
    addDock(m_suggestionPanel, tr("Suggestions"), QStringLiteral("suggestionsDock"));
    m_changesView = new ArchitectureDiffView(window);
    addDock(m_changesView, tr("Architecture changes"), QStringLiteral("changesDock"));
    m_talkersPanel = new TalkersPanel(window);
    addDock(m_talkersPanel, tr("Talkers"), QStringLiteral("talkersDock"));
    m_parameterPanel = new ParameterPanel(window);
    addDock(m_parameterPanel, tr("Parameters"), QStringLiteral("parametersDock"));
    m_correctionPanel = new CorrectionPanel(window);
    m_inspector = new InspectorPanel(window);
    addDock(m_correctionPanel, tr("Corrections"), QStringLiteral("correctionsDock"));
    addDock(m_inspector, tr("Inspector"), QStringLiteral("inspectorDock"));
    resetLayout();
    m_diagramFocus = new DiagramFocus(window, dock(Dock::Diagram));
}

QDockWidget *PanelDocks::addDock(QWidget *widget, const QString &title, const QString &name)
{
    auto *dock = new QDockWidget(title, m_window);
    dock->setObjectName(name);
    dock->setWidget(widget);
    dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                      QDockWidget::DockWidgetFloatable);
    m_docks.append(dock);
    return dock;
}

QDockWidget *PanelDocks::dock(Dock which) const
{
    return m_docks.value(int(which));
}

void PanelDocks::bringForward(Dock which)
{
    QDockWidget *d = dock(which);
    d->show();
    d->raise();
}

QList<QAction *> PanelDocks::toggleViewActions() const
{
    QList<QAction *> actions;
    for (Dock d :
         {Dock::Nodes, Dock::Launch, Dock::Diagram, Dock::Source, Dock::Suggestions, Dock::Log,
          Dock::Changes, Dock::Talkers, Dock::Parameters, Dock::Corrections, Dock::Inspector})
        actions.append(dock(d)->toggleViewAction());
    return actions;
}

void PanelDocks::takeOutDock(QDockWidget *dock)
{
    // Docked first, then taken out: a floating dock taken out stays a window of its own when
    // it is split or tabified in again (Reset Layout left a floated Log floating).
    dock->setFloating(false);
    m_window->removeDockWidget(dock);
}

void PanelDocks::resetLayout()
{
    if (m_diagramFocus)
        m_diagramFocus->setFocused(false); // the panels it hid come back with the rest
    QDockWidget *nodes = dock(Dock::Nodes);
    QDockWidget *launch = dock(Dock::Launch);
    QDockWidget *diagram = dock(Dock::Diagram);
    QDockWidget *source = dock(Dock::Source);
    QDockWidget *log = dock(Dock::Log);
    QDockWidget *suggestions = dock(Dock::Suggestions);
    const QList<QDockWidget *> docks{nodes, launch, diagram, source, log, suggestions};
    for (QDockWidget *d : docks)
        takeOutDock(d);
    // One nested dock area fills the window (there is no central widget): the model views
    // side by side on top (atomic nodes | launch tree | diagram | source), the log across the
    // bottom. Growing the window grows them all. In a small window the Log takes the whole bottom
    // row, Suggestions a tab beside it: side by side at 1024 px its filter bar took three lines and
    // the table showed two findings.
    const bool small = isSmallLayout(m_window->size());
    m_window->addDockWidget(Qt::TopDockWidgetArea, nodes);
    m_window->splitDockWidget(nodes, small ? log : suggestions, Qt::Vertical);
    if (small)
        m_window->tabifyDockWidget(log, suggestions);
    else
        m_window->splitDockWidget(suggestions, log, Qt::Horizontal);
    m_window->splitDockWidget(nodes, launch, Qt::Horizontal);
    m_window->splitDockWidget(launch, diagram, Qt::Horizontal);
    m_window->splitDockWidget(diagram, source, Qt::Horizontal);
    for (QDockWidget *d : docks)
        d->show();
    // Architecture changes and talkers share the log's place and appear when a comparison
    // runs or a topic, service, action or port is clicked; the parameters of what is selected
    // are a tab there from the start.
    QDockWidget *parameters = dock(Dock::Parameters);
    for (QDockWidget *d : {dock(Dock::Changes), dock(Dock::Talkers), parameters}) {
        takeOutDock(d);
        m_window->tabifyDockWidget(log, d);
        d->setVisible(d == parameters);
    }
    placeCorrectionDocks();
    log->raise();
    for (QToolBar *bar : m_window->findChildren<QToolBar *>())
        if (bar->parentWidget() == m_window)
            bar->show();
    const int w = std::max(m_window->width(), 800);
    const int h = std::max(m_window->height(), 600);
    m_window->resizeDocks({nodes, launch, diagram, source},
                          {w * 2 / 10, w * 2 / 10, w * 4 / 10, w * 2 / 10}, Qt::Horizontal);
    if (small) {
        m_window->resizeDocks({nodes, log}, {h * 6 / 10, h * 4 / 10}, Qt::Vertical);
        return;
    }
    m_window->resizeDocks({nodes, suggestions}, {h * 7 / 10, h * 3 / 10}, Qt::Vertical);
    m_window->resizeDocks({suggestions, log}, {w / 2, w / 2}, Qt::Horizontal);
}

void PanelDocks::placeCorrectionDocks()
{
    // The corrections share the log's place; the inspector sits under the source view.
    QDockWidget *corrections = dock(Dock::Corrections);
    QDockWidget *inspector = dock(Dock::Inspector);
    QDockWidget *source = dock(Dock::Source);
    takeOutDock(corrections);
    takeOutDock(inspector);
    m_window->tabifyDockWidget(dock(Dock::Log), corrections);
    corrections->show();
    m_window->splitDockWidget(source, inspector, Qt::Vertical);
    inspector->show();
    const int h = std::max(m_window->height(), 600);
    m_window->resizeDocks({source, inspector}, {h * 5 / 10, h * 2 / 10}, Qt::Vertical);
}

void PanelDocks::restoreLayout()
{
    AppSettings settings;
    const QByteArray geometry = settings.windowGeometry();
    if (geometry.isEmpty() || !m_window->restoreGeometry(geometry)) {
        const QScreen *screen = m_window->screen();
        const QRect available = screen ? screen->availableGeometry() : QRect(0, 0, 1600, 1000);
        // A small screen is given whole: nine tenths of 1024 x 700 left the docks too little.
        const bool smallScreen = available.width() < 1280 || available.height() < 800;
        if (smallScreen)
            m_window->setGeometry(available);
        else
            m_window->resize(std::min(1440, available.width() * 9 / 10),
                             std::min(900, available.height() * 9 / 10));
        resetLayout();
    }
    // A layout saved in a window of the other size class (the large one's side-by-side Log on
    // a small screen) would be cramped: the layout of this size is made instead.
    const QSize savedAt = settings.windowStateSize();
    if (!savedAt.isValid() || isSmallLayout(savedAt) == isSmallLayout(m_window->size()))
        m_window->restoreState(settings.windowState());
    else
        resetLayout();
    m_logView->filterBar()->restoreState(settings.logFilter());
}

void PanelDocks::saveLayout()
{
    m_diagramFocus->setFocused(false); // the layout to come back to, not the focus
    AppSettings settings;
    settings.setWindowGeometry(m_window->saveGeometry());
    settings.setWindowState(m_window->saveState());
    settings.setWindowStateSize(m_window->size());
    settings.setLogFilter(m_logView->filterBar()->state());
}

bool PanelDocks::isSmallLayout(const QSize &size)
{
    return size.width() < 1280 || size.height() < 800;
}

} // namespace rosarch
