#include "widgets/diagram/diagrampanel.h"
#include "core/visibletext.h"
#include "diagram/diagramlayouter.h"
#include "jobs/stallprobe.h"
#include "widgets/diagram/diagrambreadcrumbbar.h"
#include "widgets/diagram/diagramfirstview.h"
#include "widgets/diagram/diagramminimap.h"
#include "widgets/diagram/diagramnodeitem.h"
#include "widgets/diagram/diagramrootpicker.h"
#include "widgets/diagram/diagramrootprompt.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramtext.h"
#include "widgets/diagram/diagramview.h"

#include <QAction>
#include <QCoreApplication>
#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QResizeEvent>
#include <QScrollBar>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace rosarch {

namespace {
QAction *toggle(QToolBar *bar, const QString &text, const QString &toolTip)
{
    QAction *a = bar->addAction(text);
    a->setCheckable(true);
    a->setChecked(true);
    a->setToolTip(toolTip);
    return a;
}
} // namespace

namespace {

/// Where a person looks in the diagram: the element they look at (the selection when in
/// sight, else the box nearest the middle of the view) and where it is in the view, or the
/// point in the middle when there is no such element.
struct ViewAnchor
{
    QString key;
    QPointF offset; ///< from the middle of the view to the element's corner (scene units)
    QPointF centre; ///< the middle of the view (scene coordinates)
    QPoint at;      ///< where the element's corner is in the viewport (pixels)

    static ViewAnchor of(const DiagramScene &scene, const QGraphicsView &view,
                         const QStringList &selected)
    {
        ViewAnchor a;
        const QRectF shown = view.mapToScene(view.viewport()->rect()).boundingRect();
        a.centre = shown.center();
        for (const QString &key : selected)
            if (const DiagramItem *item = scene.item(key);
                item && shown.intersects(item->sceneBoundingRect())) {
                a.key = key;
                a.offset = item->sceneBoundingRect().topLeft() - a.centre;
                a.at = view.mapFromScene(item->sceneBoundingRect().topLeft());
                return a;
            }
        qreal nearest = -1;
        for (QGraphicsItem *item : scene.items(shown)) {
            const auto *box = dynamic_cast<const DiagramNodeItem *>(item);
            if (!box)
                continue;
            const QPointF corner = box->sceneBoundingRect().topLeft();
            const qreal distance = (corner - a.centre).manhattanLength();
            if (nearest < 0 || distance < nearest) {
                nearest = distance;
                a.key = box->key();
                a.offset = corner - a.centre;
                a.at = view.mapFromScene(corner);
            }
        }
        return a;
    }

    void restore(const DiagramScene &scene, QGraphicsView *view) const
    {
        const DiagramItem *item = key.isEmpty() ? nullptr : scene.item(key);
        view->centerOn(item ? item->sceneBoundingRect().topLeft() - offset : centre);
        if (!item)
            return;
        // The new drawing may add or drop a scroll bar, which moves the middle of the view:
        // the corner goes back to its pixel.
        const QPoint moved = view->mapFromScene(item->sceneBoundingRect().topLeft()) - at;
        view->horizontalScrollBar()->setValue(view->horizontalScrollBar()->value() + moved.x());
        view->verticalScrollBar()->setValue(view->verticalScrollBar()->value() + moved.y());
    }
};

} // namespace

DiagramPanel::DiagramPanel(DiagramLayouter *layouter, QWidget *parent)
    : QWidget(parent), m_layouter(layouter), m_rootPicker(new DiagramRootPicker(this)),
      m_breadcrumbs(new DiagramBreadcrumbBar(this)), m_rootPrompt(new DiagramRootPrompt(this)),
      m_toolBar(new QToolBar(this)), m_viewBar(new QToolBar(this)), m_search(new QLineEdit(this)),
      m_scene(new DiagramScene(this)), m_view(new DiagramView(this))
{
    m_search->setPlaceholderText(tr("Find in diagram"));
    m_search->setToolTip(tr("Highlights the parts, topics, services and namespaces whose name "
                            "contains this text. Enter goes to the next match."));
    m_search->setClearButtonEnabled(true);
    m_search->setMaximumWidth(220);
    for (QToolBar *bar : {m_toolBar, m_viewBar}) {
        bar->setIconSize(QSize(16, 16));
        bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    }
    m_search->setMinimumWidth(fontMetrics().averageCharWidth() * 14);
    m_toolBar->addWidget(m_search);
    m_matchCount = new QLabel(this);
    m_matchCount->setForegroundRole(QPalette::PlaceholderText);
    m_matchCount->setContentsMargins(4, 0, 4, 0);
    m_toolBar->addWidget(m_matchCount);
    m_toolBar->addSeparator();
    m_showParameters =
        toggle(m_toolBar, tr("Parameters"), tr("Show ports whose name comes from a parameter"));
    m_showInactive = toggle(m_toolBar, tr("Inactive"),
                            tr("Show parts and ports whose launch condition or guard is false "
                               "(hidden at first: a system is read as it runs)"));
    m_showInactive->setChecked(false);
    m_options.showInactive = false;
    m_showExternal = toggle(m_toolBar, tr("External"),
                            tr("Show includes of launch files outside the workspace"));
    // The view's own commands: beside the filters, or below them in a narrow dock (at
    // 1024 px the diagram's share hid Overview, Expand All and Export behind an arrow).
    QAction *zoomOut = m_viewBar->addAction(tr("−"), m_view, &DiagramView::zoomOut);
    zoomOut->setToolTip(tr("Zoom out (-, Ctrl+wheel)"));
    QAction *zoomIn = m_viewBar->addAction(tr("+"), m_view, &DiagramView::zoomIn);
    zoomIn->setToolTip(tr("Zoom in (+, Ctrl+wheel)"));
    QAction *fit = m_viewBar->addAction(tr("Fit"), m_view, &DiagramView::fitDiagram);
    fit->setToolTip(tr("Fit the whole diagram in the view (0); a diagram too big to read "
                       "whole stops at a legible size, the minimap shows the rest"));
    m_overviewAction = m_viewBar->addAction(tr("Overview"), this, &DiagramPanel::showOverview);
    m_overviewAction->setToolTip(tr("Collapse namespaces to one box each and hide the ports of "
                                    "every part; double-click a box to expand it"));
    m_expandAllAction = m_viewBar->addAction(tr("Expand All"), this, &DiagramPanel::expandAll);
    m_expandAllAction->setToolTip(tr("Show every namespace and port of this diagram"));
    m_exportAction = m_viewBar->addAction(tr("Export…"), this, [this] {
        const QString path = QFileDialog::getSaveFileName(
            this, tr("Export Diagram"),
            composite() ? composite()->stem + QStringLiteral(".svg") : QString(),
            tr("SVG image (*.svg);;PNG image (*.png)"));
        if (!path.isEmpty())
            path.endsWith(QLatin1String(".png"), Qt::CaseInsensitive) ? exportPng(path)
                                                                      : exportSvg(path);
    });
    m_exportAction->setToolTip(tr("Save the whole diagram as SVG or PNG"));

    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    auto *header = new QHBoxLayout;
    header->setContentsMargins(4, 2, 0, 2);
    header->setSpacing(4);
    header->addWidget(m_rootPicker);
    header->addWidget(m_breadcrumbs, 1);
    layout->addLayout(header);
    m_tools = new QBoxLayout(QBoxLayout::LeftToRight);
    m_tools->setContentsMargins(0, 0, 0, 0);
    m_tools->setSpacing(0);
    m_tools->addWidget(m_toolBar);
    m_tools->addWidget(m_viewBar, 1);
    layout->addLayout(m_tools);
    layout->addWidget(m_rootPrompt, 1);
    layout->addWidget(m_view, 1);
    m_rootPrompt->hide();
    m_view->setScene(m_scene);
    m_scene->setDiagramStyle(DiagramStyle::fromPalette(palette()));
    m_view->setLegibleZoom(legibleZoom());

    connect(m_search, &QLineEdit::textChanged, this, [this] { updateSearch(true); });
    connect(m_search, &QLineEdit::returnPressed, this, &DiagramPanel::findNext);
    for (QAction *a : {m_showParameters, m_showInactive, m_showExternal})
        connect(a, &QAction::toggled, this, &DiagramPanel::onFilterToggled);
    connect(m_breadcrumbs, &DiagramBreadcrumbBar::crumbClicked, this, &DiagramPanel::showComposite);
    connect(m_scene, &QGraphicsScene::sceneRectChanged, m_view->minimap(),
            &DiagramMinimap::refresh);
    connect(m_rootPicker, &DiagramRootPicker::rootChosen, this, &DiagramPanel::onRootChosen);
    connect(m_rootPrompt, &DiagramRootPrompt::rootChosen, this, &DiagramPanel::onRootChosen);
    connect(m_scene, &DiagramScene::elementClicked, this, &DiagramPanel::onElementClicked);
    connect(m_scene, &DiagramScene::elementDoubleClicked, this,
            &DiagramPanel::onElementDoubleClicked);
    connect(m_scene, &DiagramScene::elementContextMenuRequested, this,
            &DiagramPanel::onContextMenu);
    m_emptyText = tr("No composed diagram yet. Run stage 3 to compose the launch files.");
    showMessage(m_emptyText);
}

void DiagramPanel::setDescriber(const std::function<QString(const QString &)> &describer)
{
    m_describer = describer;
}

void DiagramPanel::setEmptyText(const QString &text)
{
    if (text == m_emptyText)
        return;
    m_emptyText = text;
    if (m_architecture.composites.isEmpty())
        showMessage(m_emptyText);
}

DiagramPanel::~DiagramPanel()
{
    if (m_pending && m_layouter)
        m_layouter->cancel(); // a running helper is killed; its result is dropped
}

void DiagramPanel::setArchitecture(const Architecture &architecture, const QList<LaunchRoot> &roots,
                                   const RootChoice &start)
{
    m_architecture = architecture;
    m_roots = roots.isEmpty() ? RootChoice::roots(m_architecture, {}) : roots;
    {
        const StallScope scope("DiagramPanel root picker and prompt");
        m_rootPicker->setRoots(m_roots);
        m_rootPrompt->setRoots(m_roots);
    }
    QString show = m_current;
    if (!m_architecture.composite(show)) {
        show.clear();
        if (start.reason == RootChoice::Reason::Ask && m_roots.size() > 1) {
            m_current.clear();
            m_scene->clearDiagram();
            updateBreadcrumbs();
            askForRoot();
            return;
        }
        if (m_architecture.composite(start.instanceId))
            show = start.instanceId;
        for (const Composite &c : std::as_const(m_architecture.composites))
            if (show.isEmpty() && c.parentId.isEmpty())
                show = c.instanceId;
        if (show.isEmpty() && !m_architecture.composites.isEmpty())
            show = m_architecture.composites.first().instanceId;
        // a system whose root only includes other launch files opens where its nodes are
        if (!show.isEmpty())
            show = DiagramFirstView::firstComposite(m_architecture, show, m_options.showInactive);
    }
    if (show.isEmpty()) {
        m_current.clear();
        updateBreadcrumbs();
        relayout();
        return;
    }
    if (show == m_current) {
        updateBreadcrumbs();
        relayout();
        return;
    }
    showComposite(show);
}

void DiagramPanel::askForRoot()
{
    m_rootPrompt->setRoots(m_roots);
    m_rootPrompt->show();
    m_view->hide();
    m_rootPicker->setCurrentRoot({});
}

bool DiagramPanel::isAskingForRoot() const
{
    return m_rootPrompt->isVisibleTo(this);
}

void DiagramPanel::onRootChosen(const QString &instanceId)
{
    if (!m_architecture.composite(instanceId))
        return;
    showComposite(
        DiagramFirstView::firstComposite(m_architecture, instanceId, m_options.showInactive));
    Q_EMIT rootChosen(instanceId);
}

void DiagramPanel::showComposite(const QString &instanceId)
{
    if (!m_architecture.composite(instanceId))
        return;
    m_rootPrompt->hide();
    m_view->show();
    if (instanceId != m_current) {
        m_current = instanceId;
        m_marks.clear();
        m_missing.clear();
        m_view->setBanner({});
        m_fitPending = true;
        m_scene->clearDiagram();
        m_view->minimap()->setKeepClear({});
    }
    updateBreadcrumbs();
    relayout();
    Q_EMIT compositeShown(instanceId);
}

QStringList DiagramPanel::breadcrumbIds() const
{
    QStringList ids;
    for (const DiagramBreadcrumbBar::Crumb &c : m_breadcrumbs->path())
        ids << c.id;
    return ids;
}

const Composite *DiagramPanel::composite() const
{
    return m_architecture.composite(m_current);
}

void DiagramPanel::setOptions(const DiagramOptions &options)
{
    m_options = options;
    const QSignalBlocker b1(m_showParameters), b2(m_showInactive), b3(m_showExternal);
    m_showParameters->setChecked(options.showParameterPorts);
    m_showInactive->setChecked(options.showInactive);
    m_showExternal->setChecked(options.showExternal);
    relayout();
}

void DiagramPanel::onFilterToggled()
{
    m_options.showParameterPorts = m_showParameters->isChecked();
    m_options.showInactive = m_showInactive->isChecked();
    m_options.showExternal = m_showExternal->isChecked();
    relayout();
}

void DiagramPanel::setMarks(const QHash<QString, DiagramMark> &marks, const QStringList &missing)
{
    m_marks = marks;
    m_missing = missing;
    m_scene->setMarks(marks);
    m_view->setBanner(DiagramText::missingBanner(missing));
}

bool DiagramPanel::exportSvg(const QString &path)
{
    const Composite *c = composite();
    return c && m_scene->exportSvg(path, c->stem);
}

bool DiagramPanel::exportPng(const QString &path)
{
    return m_scene->exportPng(path);
}

QString DiagramPanel::message() const
{
    return m_view->message();
}

void DiagramPanel::applyLayout(const LayoutGraph &graph, const LayoutResult &result, bool fit)
{
    const StallScope scope("DiagramPanel::applyLayout (scene items)");
    const Composite *c = composite();
    if (!c)
        return;
    if (!result.ok) {
        m_scene->clearDiagram();
        showMessage(tr("%1\n\nCollapse namespaces or hide elements to make the diagram "
                       "smaller, then try again.")
                        .arg(result.error));
        Q_EMIT layoutFinished(false);
        return;
    }
    if (fit && overviewInstead(DiagramScene::sceneRectFor(result.geometry.bounds).size())) {
        relayout(); // the overview instead; the drawing too small to read is not shown
        return;
    }
    m_lastLayoutMs = result.elapsedMs;
    showMessage({});
    // The composite shown drawn again (after a correction, a decision, an undo): the person's
    // place stays: the zoom (the view's transform), what is selected, and where the element
    // they look at is in the view, even when the new layout moved it. Clearing the scene would
    // otherwise scroll the view to its start.
    const bool redrawn = !fit && !m_scene->sceneRect().isEmpty();
    const QStringList selected = selectedKeys();
    const ViewAnchor anchor = redrawn ? ViewAnchor::of(*m_scene, *m_view, selected) : ViewAnchor();
    m_scene->setDiagram(graph, result.geometry, visibleText(c->stem), DiagramText::frameDetail(*c));
    QHash<QString, QString> tips = DiagramText::toolTips(*c);
    if (m_describer) // what each node does, as the inspector and the node list say it
        for (const RosNodePart &part : c->parts)
            if (part.kind == RosNodePart::Kind::Node)
                if (const QString said = m_describer(part.typeId); !said.isEmpty())
                    tips[DiagramBuilder::partKey(part.id)] += QLatin1Char('\n') + said;
    m_scene->setToolTips(tips);
    m_scene->setMarks(m_marks);
    updateSearch(false);
    if (fit) {
        m_view->fitDiagram();
        m_fitPending = false;
    } else if (redrawn) {
        // The scroll bars a new scene size brings or drops come a turn later (queued by the
        // scroll area), and the view keeps its middle then: they come first, so the element
        // goes back to its pixel in the view as it will stay.
        QCoreApplication::sendPostedEvents(m_view, QEvent::MetaCall);
        anchor.restore(*m_scene, m_view);
        for (const QString &key : selected)
            if (DiagramItem *item = m_scene->item(key))
                item->setSelected(true);
        if (const DiagramItem *item = m_scene->item(m_expanded))
            showExpanded(*item);
    }
    m_expanded.clear();
    m_overviewAction->setEnabled(true);
    m_expandAllAction->setEnabled(isCollapsed());
    Q_EMIT layoutFinished(true);
}

void DiagramPanel::showExpanded(const DiagramItem &item)
{
    // Expanded in place: its corner where the box's was, then moved as little as needed to
    // show all of it; bigger than the view, it fills the view from its top left corner.
    const QRectF rect = item.sceneBoundingRect();
    const QPointF shift = m_view->mapToScene(m_expandedAt.toPoint()) - rect.topLeft();
    const QRectF shown = m_view->mapToScene(m_view->viewport()->rect()).boundingRect();
    m_view->centerOn(shown.center() - shift);
    const QRectF view = m_view->mapToScene(m_view->viewport()->rect()).boundingRect();
    const qreal margin = 8 / std::max(m_view->zoom(), 0.01);
    if (rect.width() + 2 * margin <= view.width() && rect.height() + 2 * margin <= view.height())
        m_view->ensureVisible(rect, int(margin * m_view->zoom()), int(margin * m_view->zoom()));
    else
        m_view->centerOn(rect.topLeft() - QPointF(margin, margin) + view.center() - view.topLeft());
}

void DiagramPanel::showMessage(const QString &text)
{
    m_view->setMessage(text);
}

void DiagramPanel::updateBreadcrumbs()
{
    QList<DiagramBreadcrumbBar::Crumb> path;
    QStringList seen;
    for (const Composite *c = composite(); c && !seen.contains(c->instanceId);
         c = m_architecture.composite(c->parentId)) {
        seen << c->instanceId;
        // names of files: shown with their control characters escaped, on one line
        path.prepend({c->instanceId, visibleText(c->stem),
                      visibleText(c->file.isEmpty() ? c->stem : c->file)});
    }
    // Whose view: an included file is shown as that include resolves it (blueprint §1); its
    // exported CCD is the file on its own.
    QString note, tip;
    if (path.size() > 1) {
        note = tr("as included by %1").arg(path.at(path.size() - 2).label);
        tip = tr("Names, namespaces and arguments are resolved for this include of %1. The "
                 "exported CCD of %1 is the file on its own, with its declared defaults.")
                  .arg(path.last().label);
    } else if (!path.isEmpty()) {
        note = tr("as launched");
        tip = tr("The root launch file with the launch arguments of the run.");
    }
    m_breadcrumbs->setPath(path, note, tip);
    m_rootPicker->setCurrentRoot(path.isEmpty() ? QString() : path.first().id);
}

void DiagramPanel::updateSearch(bool centre)
{
    m_matches = m_scene->find(m_search->text());
    m_scene->setMatches(m_matches);
    m_matchIndex = m_matches.isEmpty() ? -1 : 0;
    if (centre && m_matchIndex >= 0)
        selectKey(m_matches.first());
    if (m_matchIndex < 0)
        m_view->minimap()->setKeepClear({});
    m_matchCount->setText(matchText());
}

void DiagramPanel::findNext()
{
    if (m_matches.isEmpty())
        return;
    m_matchIndex = (m_matchIndex + 1) % m_matches.size();
    selectKey(m_matches[m_matchIndex]);
    m_matchCount->setText(matchText());
}

QString DiagramPanel::matchText() const
{
    if (m_search->text().trimmed().isEmpty())
        return {};
    if (m_matches.isEmpty())
        return tr("No match");
    return tr("%1 of %2").arg(m_matchIndex + 1).arg(m_matches.size());
}

void DiagramPanel::focusSearch()
{
    m_search->setFocus(Qt::ShortcutFocusReason);
    m_search->selectAll();
}

void DiagramPanel::selectKey(const QString &key)
{
    DiagramItem *item = m_scene->item(key);
    if (!item)
        return;
    m_scene->clearSelection();
    item->setSelected(true);
    m_view->centerOn(item);
    m_view->minimap()->setKeepClear(item->sceneBoundingRect()); // never under the minimap
}

QString DiagramPanel::drawnKey(const RosNodePart &part) const
{
    // Inside a collapsed namespace, the namespace's box stands for the part.
    for (const QString &ns : DiagramBuilder::namespaceChain(part.nameSpace))
        if (isNamespaceCollapsed(ns))
            return DiagramBuilder::namespaceKey(ns);
    return DiagramBuilder::partKey(part.id);
}

bool DiagramPanel::selectInstance(const QString &instanceId)
{
    const Composite *c = composite();
    if (!c)
        return false;
    for (const RosNodePart &part : c->parts) {
        if (part.instanceId != instanceId)
            continue;
        const QString key = drawnKey(part);
        if (!m_scene->item(key))
            return false;
        selectKey(key);
        return true;
    }
    return false;
}

void DiagramPanel::onElementClicked(const QString &key)
{
    const Composite *c = composite();
    if (!c)
        return;
    const DiagramKey k = DiagramKey::parse(key);
    if (k.kind == DiagramKey::Kind::Part) {
        if (const RosNodePart *part = c->part(k.id))
            Q_EMIT partActivated(part->instanceId);
    } else if (k.kind == DiagramKey::Kind::Port) {
        if (DiagramBuilder::port(*c, k.id, k.portId))
            Q_EMIT portActivated(c->part(k.id)->instanceId, k.portId);
    } else if (k.kind == DiagramKey::Kind::Connection) {
        // An edge stands for its part's port: the part is selected with it, everywhere.
        const int i = k.index();
        if (i >= 0 && i < c->connections.size())
            if (const RosNodePart *part = c->part(c->connections.at(i).partId)) {
                m_scene->selectAlso(drawnKey(*part));
                Q_EMIT partActivated(part->instanceId);
            }
    }
    Q_EMIT elementActivated(key);
    const Evidence evidence = DiagramBuilder::evidence(*c, key);
    if (evidence.isValid())
        Q_EMIT evidenceActivated(evidence);
}

QStringList DiagramPanel::selectedKeys() const
{
    QStringList keys;
    for (QGraphicsItem *item : m_scene->selectedItems())
        if (auto *d = dynamic_cast<DiagramItem *>(item))
            keys.append(d->key());
    keys.sort();
    return keys;
}

void DiagramPanel::selectElement(const QString &key)
{
    selectKey(key);
}

void DiagramPanel::activateElement(const QString &key)
{
    if (!m_scene->item(key))
        return;
    selectKey(key);
    onElementClicked(key);
}

void DiagramPanel::resizeEvent(QResizeEvent *event)
{
    QWidget::resizeEvent(event);
    const bool oneRow =
        m_toolBar->sizeHint().width() + m_viewBar->sizeHint().width() <= event->size().width();
    m_tools->setDirection(oneRow ? QBoxLayout::LeftToRight : QBoxLayout::TopToBottom);
}

void DiagramPanel::changeEvent(QEvent *event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange) {
        m_scene->setDiagramStyle(DiagramStyle::fromPalette(palette()));
        m_view->minimap()->refresh();
    }
}

} // namespace rosarch
