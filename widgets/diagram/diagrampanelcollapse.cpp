// The composed diagram panel's collapsing and expanding: namespaces drawn as one box, parts
// drawn without their ports, the overview a diagram too big to read starts in, and the element
// actions (double-click, context menu) that collapse, expand and open.
#include "diagram/diagramoverview.h"
#include "widgets/diagram/diagramfirstview.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/diagram/diagramview.h"

#include <QAction>
#include <QMenu>

namespace rosarch {

void DiagramPanel::setNamespaceCollapsed(const QString &nameSpace, bool collapsed)
{
    QStringList &list = m_collapsed[m_current];
    if (collapsed == list.contains(nameSpace))
        return;
    if (collapsed)
        list << nameSpace;
    else
        list.removeAll(nameSpace);
    list.sort();
    relayout();
}

bool DiagramPanel::isNamespaceCollapsed(const QString &nameSpace) const
{
    return m_collapsed.value(m_current).contains(nameSpace);
}

void DiagramPanel::setPartCompact(const QString &partId, bool compact)
{
    QStringList &list = m_compact[m_current];
    if (compact == list.contains(partId))
        return;
    if (compact)
        list << partId;
    else
        list.removeAll(partId);
    list.sort();
    relayout();
}

bool DiagramPanel::isPartCompact(const QString &partId) const
{
    return m_compact.value(m_current).contains(partId);
}

void DiagramPanel::setBoundaryCollapsed(bool collapsed)
{
    if (collapsed == isBoundaryCollapsed())
        return;
    if (collapsed)
        m_boundaryCollapsed.insert(m_current);
    else
        m_boundaryCollapsed.remove(m_current);
    relayout();
}

void DiagramPanel::showOverview()
{
    const Composite *c = composite();
    if (!c)
        return;
    const DiagramOptions overview = DiagramOverview::options(*c, m_options);
    m_collapsed[m_current] = overview.collapsedNamespaces;
    m_compact[m_current] = overview.compactParts;
    m_boundaryCollapsed.insert(m_current);
    m_sizeChecked.insert(m_current);
    m_fitPending = true;
    relayout();
}

void DiagramPanel::expandAll()
{
    m_collapsed.remove(m_current);
    m_compact.remove(m_current);
    m_boundaryCollapsed.remove(m_current);
    m_sizeChecked.insert(m_current);
    m_fitPending = true;
    relayout();
}

bool DiagramPanel::isCollapsed() const
{
    return !m_collapsed.value(m_current).isEmpty() || !m_compact.value(m_current).isEmpty() ||
           isBoundaryCollapsed();
}

qreal DiagramPanel::legibleZoom() const
{
    // The names of topics, services and boundary ports (the text font); part names are bigger.
    const QFont &font = m_scene->diagramStyle().textFont;
    const double pixels =
        font.pixelSize() > 0 ? font.pixelSize() : font.pointSizeF() * logicalDpiY() / 72.0;
    return DiagramOverview::legibleZoom(kLegiblePoints, logicalDpiY(), pixels);
}

DiagramOptions DiagramPanel::currentOptions() const
{
    DiagramOptions options = m_options;
    options.collapsedNamespaces = m_collapsed.value(m_current);
    options.compactParts = m_compact.value(m_current);
    options.collapseBoundary = isBoundaryCollapsed();
    return options;
}

bool DiagramPanel::overviewInstead(const QSizeF &size)
{
    // A view not on screen has no size to fit: decide when it is shown and fitted.
    if (m_sizeChecked.contains(m_current) || !m_fitPending || !m_view->isVisible())
        return false;
    const qreal fit = m_view->fitZoom(size);
    const qreal legible = m_view->legibleZoom();
    const Composite *c = composite();
    if (!c || fit >= legible || fit <= 0) {
        m_sizeChecked.insert(m_current);
        return false;
    }
    const QList<DiagramOptions> steps = DiagramFirstView::steps(*c, m_options);
    const int step = DiagramFirstView::indexOf(steps, currentOptions());
    QHash<int, qreal> &tried = m_firstViewFits[m_current];
    tried.insert(step, fit);
    if (step == steps.size() - 1 || tried.size() > kFirstViewTries) {
        // Nothing tried can be read whole: the one that shows most of itself, and of those the
        // one that collapses least. Drawing less does not always draw smaller: namespaces
        // stacked in a column become a long row of boxes.
        m_sizeChecked.insert(m_current);
        int best = step;
        for (auto it = tried.cbegin(); it != tried.cend(); ++it)
            if (it.key() >= 0 &&
                (it.value() > tried.value(best) ||
                 (qFuzzyCompare(it.value(), tried.value(best)) && it.key() < best)))
                best = it.key();
        if (best == step)
            return false;
        setCollapse(steps[best]);
        return true; // laid out before: the layouter has it cached
    }
    // The layout is bigger than its boxes promised: the next build asks for boxes that much
    // smaller (the zoom scales both sides).
    const double shortBy = (legible / fit) * (legible / fit);
    m_retryArea = m_lastBoxArea / shortBy;
    return true;
}

void DiagramPanel::setCollapse(const DiagramOptions &options)
{
    m_collapsed[m_current] = options.collapsedNamespaces;
    m_compact[m_current] = options.compactParts;
    if (options.collapseBoundary)
        m_boundaryCollapsed.insert(m_current);
    else
        m_boundaryCollapsed.remove(m_current);
}

void DiagramPanel::keepInView(const QString &key)
{
    const DiagramItem *item = m_scene->item(key);
    if (!item)
        return;
    m_expanded = key;
    m_expandedAt = m_view->mapFromScene(item->sceneBoundingRect().topLeft());
}

void DiagramPanel::onElementDoubleClicked(const QString &key)
{
    const Composite *c = composite();
    const DiagramKey k = DiagramKey::parse(key);
    if (!c)
        return;
    if (k.kind == DiagramKey::Kind::Part) {
        const RosNodePart *part = c->part(k.id);
        if (part && part->kind == RosNodePart::Kind::Launch &&
            m_architecture.composite(part->instanceId))
            showComposite(part->instanceId);
        else if (part && isPartCompact(part->id)) {
            keepInView(key);
            setPartCompact(part->id, false);
        }
    } else if (k.kind == DiagramKey::Kind::Namespace && isNamespaceCollapsed(k.id)) {
        keepInView(key);
        setNamespaceCollapsed(k.id, false);
    } else if (k.kind == DiagramKey::Kind::Boundary && isBoundaryCollapsed()) {
        setBoundaryCollapsed(false);
    }
}

QList<QAction *> DiagramPanel::elementActions(const QString &key)
{
    QList<QAction *> actions;
    const Composite *c = composite();
    const DiagramKey k = DiagramKey::parse(key);
    if (!c)
        return actions;
    if (k.kind == DiagramKey::Kind::Namespace) {
        const bool collapsed = isNamespaceCollapsed(k.id);
        auto *a = new QAction(collapsed ? tr("Expand Namespace %1").arg(k.id)
                                        : tr("Collapse Namespace %1").arg(k.id),
                              this);
        connect(a, &QAction::triggered, this,
                [this, ns = k.id, collapsed] { setNamespaceCollapsed(ns, !collapsed); });
        actions << a;
    } else if (k.kind == DiagramKey::Kind::Part) {
        const RosNodePart *part = c->part(k.id);
        if (part && part->kind == RosNodePart::Kind::Launch &&
            m_architecture.composite(part->instanceId)) {
            auto *a = new QAction(tr("Open %1").arg(part->typeName), this);
            connect(a, &QAction::triggered, this,
                    [this, id = part->instanceId] { showComposite(id); });
            actions << a;
        }
        if (part) {
            const bool compact = isPartCompact(part->id);
            const QString name = part->name.isEmpty() ? part->typeName : part->name;
            auto *a = new QAction(compact ? tr("Show Ports of %1").arg(name)
                                          : tr("Hide Ports of %1").arg(name),
                                  this);
            connect(a, &QAction::triggered, this,
                    [this, id = part->id, compact] { setPartCompact(id, !compact); });
            actions << a;
        }
        const QStringList chain =
            part ? DiagramBuilder::namespaceChain(part->nameSpace) : QStringList();
        if (!chain.isEmpty()) {
            auto *a = new QAction(tr("Collapse Namespace %1").arg(chain.last()), this);
            connect(a, &QAction::triggered, this,
                    [this, ns = chain.last()] { setNamespaceCollapsed(ns, true); });
            actions << a;
        }
    }
    if (k.kind == DiagramKey::Kind::Boundary) {
        const bool collapsed = isBoundaryCollapsed();
        auto *a = new QAction(
            collapsed ? tr("Show Each Boundary Port") : tr("Collapse Boundary Ports"), this);
        connect(a, &QAction::triggered, this,
                [this, collapsed] { setBoundaryCollapsed(!collapsed); });
        actions << a;
    }
    if (isCollapsed()) {
        auto *a = new QAction(tr("Expand All"), this);
        connect(a, &QAction::triggered, this, &DiagramPanel::expandAll);
        actions << a;
    }
    return actions;
}

void DiagramPanel::onContextMenu(const QString &key, const QPoint &screenPos)
{
    const QList<QAction *> actions = elementActions(key);
    QMenu menu(this);
    Q_EMIT elementMenuRequested(key, &menu);
    if (!menu.isEmpty() && !actions.isEmpty())
        menu.addSeparator();
    menu.addActions(actions);
    if (!menu.isEmpty())
        menu.exec(screenPos);
    qDeleteAll(actions);
}

} // namespace rosarch
