#include "filterboxes.h"

#include "app/mainwindow.h"
#include "widgets/atomicnodemodel.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticfilterbar.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/parameterpanel.h"
#include "widgets/parametertablemodel.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QSortFilterProxyModel>
#include <QTableView>
#include <QTreeView>

namespace rosarch {

namespace {

/// Shows and raises the dock `widget` is in (a tab behind another one is not painted).
void bringForward(QWidget *widget)
{
    for (QWidget *w = widget; w; w = w->parentWidget())
        if (auto *dock = qobject_cast<QDockWidget *>(w)) {
            dock->show();
            dock->raise();
            return;
        }
}

/// The rows a tree view shows (those under expanded rows), counted as it lays them out: the
/// count costs what the view costs, not a walk of every row the filter kept.
QString rowsText(const QTreeView *view)
{
    int rows = 0;
    for (QModelIndex i = view->model()->index(0, 0); i.isValid(); i = view->indexBelow(i))
        ++rows;
    return QStringLiteral("%1 rows shown").arg(rows);
}

/// Selects the node class that declares the most parameters, so that the Parameters panel has
/// the most to filter.
void selectClassWithMostParameters(MainWindow &w)
{
    auto *model = w.findChild<AtomicNodeModel *>();
    auto *nodes = w.findChild<AtomicNodePanel *>();
    auto *parameters = w.findChild<ParameterPanel *>();
    QModelIndex best;
    int most = -1;
    for (int p = 0; p < model->rowCount(); ++p) {
        const QModelIndex package = model->index(p, 0);
        for (int n = 0; n < model->rowCount(package); ++n) {
            const QModelIndex node = model->index(n, 0, package);
            if (model->kind(node) != AtomicNodeModel::ItemKind::Node)
                continue;
            nodes->selectSourceIndex(node);
            QCoreApplication::processEvents();
            if (const int rows = parameters->model()->rowCount(); rows > most) {
                most = rows;
                best = node;
            }
        }
    }
    if (best.isValid())
        nodes->selectSourceIndex(best);
}

/// Shows the largest composite the panel lays out, in full, so that the search has the most
/// to look through; waits for its layout.
void showLargestComposite(DiagramPanel *panel)
{
    const Composite *largest = nullptr;
    for (const Composite &c : panel->architecture().composites)
        if (c.parts.size() + c.channels.size() <= DiagramPanel::kMaxLayoutNodes &&
            (!largest || c.parts.size() > largest->parts.size()))
            largest = &c;
    if (!largest)
        return;
    panel->showComposite(largest->instanceId);
    QElapsedTimer waited;
    waited.start();
    const auto settle = [&] {
        while (panel->isLayingOut() && waited.elapsed() < 60000)
            QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    };
    settle();
    panel->expandAll();
    settle();
}

} // namespace

QList<FilterBox> filterBoxes(MainWindow &w)
{
    // The panels are found once: a lookup per key press would be measured with the filter.
    auto *nodes = w.findChild<AtomicNodePanel *>();
    auto *launch = w.findChild<LaunchTreePanel *>();
    auto *log = w.findChild<LogView *>();
    auto *parameters = w.findChild<ParameterPanel *>();
    auto *diagram = w.findChild<DiagramPanel *>();
    QList<FilterBox> boxes;
    boxes.append({QStringLiteral("node list"), nodes->filterEdit(),
                  [nodes] { bringForward(nodes); },
                  [nodes] { return rowsText(nodes->treeView()); }});
    boxes.append({QStringLiteral("launch tree"), launch->filterEdit(),
                  [launch] { bringForward(launch); },
                  [launch] { return rowsText(launch->treeView()); }});
    boxes.append({QStringLiteral("findings"), log->filterBar()->searchEdit(),
                  [log] { bringForward(log); },
                  [log] { return rowsText(log->diagnosticsView()); }});
    boxes.append({QStringLiteral("parameters"), parameters->filter(),
                  [&w, parameters] {
                      selectClassWithMostParameters(w);
                      bringForward(parameters);
                  },
                  [parameters] {
                      return QStringLiteral("%1 of %2 parameters")
                          .arg(parameters->proxy()->rowCount())
                          .arg(parameters->model()->rowCount());
                  }});
    boxes.append({QStringLiteral("diagram find"), diagram->searchField(),
                  [diagram] {
                      bringForward(diagram);
                      showLargestComposite(diagram);
                  },
                  [diagram] {
                      const QString text = diagram->matchText();
                      return text.isEmpty() ? QStringLiteral("no search") : text;
                  }});
    return boxes;
}

} // namespace rosarch
