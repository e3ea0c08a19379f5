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
    AtomicNodeModel *model = w.nodeModel();
    QModelIndex best;
    int most = -1;
    for (int p = 0; p < model->rowCount(); ++p) {
        const QModelIndex package = model->index(p, 0);
        for (int n = 0; n < model->rowCount(package); ++n) {
            const QModelIndex node = model->index(n, 0, package);
            if (model->kind(node) != AtomicNodeModel::ItemKind::Node)
                continue;
            w.nodePanel()->selectSourceIndex(node);
            QCoreApplication::processEvents();
            if (const int rows = w.parameterPanel()->model()->rowCount(); rows > most) {
                most = rows;
                best = node;
            }
        }
    }
    if (best.isValid())
        w.nodePanel()->selectSourceIndex(best);
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
    QList<FilterBox> boxes;
    boxes.append({QStringLiteral("node list"), w.nodePanel()->filterEdit(),
                  [&w] { bringForward(w.nodePanel()); },
                  [&w] { return rowsText(w.nodePanel()->treeView()); }});
    boxes.append({QStringLiteral("launch tree"), w.launchPanel()->filterEdit(),
                  [&w] { bringForward(w.launchPanel()); },
                  [&w] { return rowsText(w.launchPanel()->treeView()); }});
    boxes.append({QStringLiteral("findings"), w.logView()->filterBar()->searchEdit(),
                  [&w] { bringForward(w.logView()); },
                  [&w] { return rowsText(w.logView()->diagnosticsView()); }});
    boxes.append({QStringLiteral("parameters"), w.parameterPanel()->filter(),
                  [&w] {
                      selectClassWithMostParameters(w);
                      bringForward(w.parameterPanel());
                  },
                  [&w] {
                      return QStringLiteral("%1 of %2 parameters")
                          .arg(w.parameterPanel()->proxy()->rowCount())
                          .arg(w.parameterPanel()->model()->rowCount());
                  }});
    boxes.append({QStringLiteral("diagram find"), w.diagramPanel()->searchField(),
                  [&w] {
                      bringForward(w.diagramPanel());
                      showLargestComposite(w.diagramPanel());
                  },
                  [&w] {
                      const QString text = w.diagramPanel()->matchText();
                      return text.isEmpty() ? QStringLiteral("no search") : text;
                  }});
    return boxes;
}

} // namespace rosarch
