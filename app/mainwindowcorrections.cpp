// The main window's part of corrections: the Corrections and Inspector docks, the
// controller that makes corrections where the element is, and the Model menu.
#include "app/correctioncontroller.h"
#include "app/diagramcontroller.h"
#include "app/mainwindow.h"
#include "document/document.h"
#include "widgets/correctionmodel.h"
#include "widgets/correctionpanel.h"
#include "widgets/inspectorpanel.h"

#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

namespace rosarch {

void MainWindow::createCorrectionDocks()
{
    m_correctionModel = new CorrectionModel(m_document, this);
    m_correctionPanel = new CorrectionPanel(this);
    m_correctionPanel->setModel(m_correctionModel);
    m_inspector = new InspectorPanel(this);
    const auto makeDock = [this](QWidget *widget, const QString &title, const QString &name) {
        auto *dock = new QDockWidget(title, this);
        dock->setObjectName(name);
        dock->setWidget(widget);
        dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable |
                          QDockWidget::DockWidgetFloatable);
        return dock;
    };
    m_correctionsDock =
        makeDock(m_correctionPanel, tr("Corrections"), QStringLiteral("correctionsDock"));
    m_inspectorDock = makeDock(m_inspector, tr("Inspector"), QStringLiteral("inspectorDock"));
}

void MainWindow::placeCorrectionDocks()
{
    // The corrections share the log's place; the inspector sits under the source view.
    for (QDockWidget *dock : {m_correctionsDock, m_inspectorDock}) {
        if (!dock)
            return;
        takeOutDock(dock);
    }
    tabifyDockWidget(m_logDock, m_correctionsDock);
    m_correctionsDock->show();
    splitDockWidget(m_sourceDock, m_inspectorDock, Qt::Vertical);
    m_inspectorDock->show();
    const int h = std::max(height(), 600);
    resizeDocks({m_sourceDock, m_inspectorDock}, {h * 5 / 10, h * 2 / 10}, Qt::Vertical);
}

void MainWindow::createCorrectionController()
{
    m_correctionController =
        new CorrectionController(m_document, m_nodePanel, m_launchPanel, m_diagramPanel,
                                 m_traceability, m_inspector, m_correctionPanel, this);
    connect(m_correctionController, &CorrectionController::statusMessage, statusBar(),
            &QStatusBar::showMessage);
    connect(m_document, &Document::changed, this, [this](const DocumentChange &change) {
        // a new correction is listed where a person can see and revert it; the views stay
        // where the person is (showing its element would move them)
        if (change.has(DocumentChange::Corrections) && m_document->session()->correction(change.id))
            m_correctionPanel->listCorrection(change.id);
    });
}

void MainWindow::createCorrectionMenu()
{
    QMenu *model = menuBar()->addMenu(tr("&Model"));
    // The element's own actions: what the inspector shows, rebuilt whenever the menu opens.
    connect(model, &QMenu::aboutToShow, this, [this, model] {
        model->clear();
        const QList<QAction *> actions =
            m_correctionController->actionsFor(m_correctionController->current(), model);
        if (actions.isEmpty()) {
            QAction *none = model->addAction(tr("Select an element to correct it"));
            none->setEnabled(false);
        }
        model->addActions(actions);
        model->addSeparator();
        QAction *show = model->addAction(tr("Show &Corrections"));
        connect(show, &QAction::triggered, this, [this] {
            m_correctionsDock->show();
            m_correctionsDock->raise();
        });
        QAction *inspect = model->addAction(tr("Show &Inspector"));
        connect(inspect, &QAction::triggered, this, [this] {
            m_inspectorDock->show();
            m_inspectorDock->raise();
        });
    });
    QAction *placeholder = model->addAction(tr("Select an element to correct it"));
    placeholder->setEnabled(false);
}

} // namespace rosarch
