#include "app/navigationcontroller.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/diagnosticmodel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramscene.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/sourceview.h"

#include <Qsci/qsciscintilla.h>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QMainWindow>
#include <QMouseEvent>
#include <QScopedValueRollback>
#include <QStyle>
#include <QTimer>
#include <QTreeView>

namespace rosarch {

namespace {

// Which panel names a visit when one action of a person moves several: the one that the
// others follow. A diagram click selects the launch tree's row and the class; a launch row
// selects the class; the source's cursor selects the rows of its line.
constexpr int kCompositePriority = 0;
constexpr int kNodesPriority = 1;
constexpr int kLaunchPriority = 2;
constexpr int kSourcePriority = 3;
constexpr int kFindingsPriority = 4;
constexpr int kElementPriority = 5;

// How a diagram element is remembered: by the instance it draws, a channel's name, or (for
// what is named by name already) its diagram key.
const QString kPartPrefix = QStringLiteral("part ");
const QString kChannelPrefix = QStringLiteral("channel ");
const QString kKeyPrefix = QStringLiteral("key ");

QWidget *panelWidget(const NavigationController::Panels &panels, NavigationPlace::Panel panel)
{
    switch (panel) {
    case NavigationPlace::Panel::Nodes:
        return static_cast<QWidget *>(panels.nodes);
    case NavigationPlace::Panel::Launch:
        return static_cast<QWidget *>(panels.launch);
    case NavigationPlace::Panel::Diagram:
        return static_cast<QWidget *>(panels.diagram);
    case NavigationPlace::Panel::Source:
        return static_cast<QWidget *>(panels.source);
    case NavigationPlace::Panel::Findings:
        return static_cast<QWidget *>(panels.log);
    }
    return nullptr;
}

} // namespace

NavigationController::NavigationController(Document *document, const Panels &panels,
                                           QMainWindow *window)
    : QObject(window), m_document(document), m_panels(panels), m_window(window),
      m_history(new NavigationHistory(this)),
      m_back(new QAction(window->style()->standardIcon(QStyle::SP_ArrowBack), tr("&Back"), this)),
      m_forward(
          new QAction(window->style()->standardIcon(QStyle::SP_ArrowForward), tr("&Forward"), this))
{
    m_back->setObjectName(QStringLiteral("goBackAction"));
    m_forward->setObjectName(QStringLiteral("goForwardAction"));
    m_back->setIconText(tr("Back"));
    m_forward->setIconText(tr("Forward"));
    // Alt+Left and Alt+Right everywhere (the platform's Back key may say otherwise).
    m_back->setShortcuts({QKeySequence(Qt::ALT | Qt::Key_Left), QKeySequence(Qt::Key_Back)});
    m_forward->setShortcuts({QKeySequence(Qt::ALT | Qt::Key_Right), QKeySequence(Qt::Key_Forward)});
    connect(m_back, &QAction::triggered, this, &NavigationController::goBack);
    connect(m_forward, &QAction::triggered, this, &NavigationController::goForward);
    connect(m_history, &NavigationHistory::changed, this, &NavigationController::updateActions);
    updateActions();

    connect(m_panels.nodes, &FilteredTreePanel::currentSourceIndexChanged, this,
            [this] { onTreeRow(m_panels.nodes, NavigationPlace::Panel::Nodes, kNodesPriority); });
    connect(m_panels.launch, &FilteredTreePanel::currentSourceIndexChanged, this, [this] {
        onTreeRow(m_panels.launch, NavigationPlace::Panel::Launch, kLaunchPriority);
    });
    connect(m_panels.diagram, &DiagramPanel::elementActivated, this,
            &NavigationController::onDiagramElement);
    connect(m_panels.diagram, &DiagramPanel::compositeShown, this,
            &NavigationController::onCompositeShown);
    connect(m_panels.source, &SourceView::cursorLineChanged, this,
            &NavigationController::onSourceLine);
    connect(m_panels.log->diagnosticsView()->selectionModel(), &QItemSelectionModel::currentChanged,
            this, &NavigationController::onFinding);
    qApp->installEventFilter(this); // the mouse's back and forward buttons, over any panel
}

NavigationController::~NavigationController()
{
    qApp->removeEventFilter(this);
}

bool NavigationController::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() != QEvent::MouseButtonPress && event->type() != QEvent::MouseButtonRelease)
        return false;
    const auto *mouse = static_cast<QMouseEvent *>(event);
    if (mouse->button() != Qt::BackButton && mouse->button() != Qt::ForwardButton)
        return false;
    auto *widget = qobject_cast<QWidget *>(watched);
    if (!widget || widget->window() != m_window)
        return false;
    // One step per click: on the press; the release is swallowed so no view sees it either.
    if (event->type() == QEvent::MouseButtonPress) {
        if (mouse->button() == Qt::BackButton)
            goBack();
        else
            goForward();
    }
    return true;
}

void NavigationController::goBack()
{
    NavigationPlace now;
    snapshotSource(&now);
    m_history->updateCurrent(now); // forward returns to where the person left it
    if (const NavigationPlace *place = m_history->back())
        show(*place);
}

void NavigationController::goForward()
{
    NavigationPlace now;
    snapshotSource(&now);
    m_history->updateCurrent(now);
    if (const NavigationPlace *place = m_history->forward())
        show(*place);
}

void NavigationController::clear()
{
    disconnect(m_waitForLayout);
    m_history->clear();
}

void NavigationController::offer(const NavigationPlace &place, int priority)
{
    if (m_restoring || place.key.isEmpty())
        return;
    if (place.panel == NavigationPlace::Panel::Nodes)
        m_turnNodeKey = place.key;
    else if (place.panel == NavigationPlace::Panel::Launch)
        m_turnLaunchKey = place.key;
    if (priority >= m_candidatePriority) { // the later of two alike: the person's last
        m_candidate = place;
        m_candidatePriority = priority;
    }
    if (!m_commitQueued) {
        m_commitQueued = true;
        QTimer::singleShot(0, this, &NavigationController::commit);
    }
}

void NavigationController::commit()
{
    m_commitQueued = false;
    NavigationPlace place = std::exchange(m_candidate, {});
    m_candidatePriority = -1;
    place.nodeKey = std::exchange(m_turnNodeKey, {});
    place.launchKey = std::exchange(m_turnLaunchKey, {});
    if (place.key.isEmpty() || echoesCurrent(place))
        return;
    snapshotSource(&place);
    m_history->visit(place);
}

bool NavigationController::echoesCurrent(const NavigationPlace &place) const
{
    // A view that reports late what it shows of the current place (the source pane's cursor
    // put back on the place's line, a row that followed it) names no new place: recording it
    // would drop the places ahead.
    const NavigationPlace *now = m_history->current();
    if (!now || now->samePlace(place))
        return false;
    switch (place.panel) {
    case NavigationPlace::Panel::Source:
        return place.key == now->sourceFile && place.sourceLine == now->sourceLine;
    case NavigationPlace::Panel::Nodes:
        return place.key == now->nodeKey;
    case NavigationPlace::Panel::Launch:
        return place.key == now->launchKey;
    case NavigationPlace::Panel::Diagram:
    case NavigationPlace::Panel::Findings:
        break;
    }
    return false;
}

void NavigationController::snapshotSource(NavigationPlace *place) const
{
    place->sourceFile = m_panels.source->currentFile();
    int index = 0;
    m_panels.source->editor()->getCursorPosition(&place->sourceLine, &index);
    place->sourceFirstLine = m_panels.source->editor()->firstVisibleLine();
}

void NavigationController::show(const NavigationPlace &place)
{
    // What the views report while the place is shown again is not a visit of its own.
    m_restoring = true;
    ++m_restoreGeneration;
    disconnect(m_waitForLayout);
    using P = NavigationPlace::Panel;
    if (place.panel != P::Launch && !place.launchKey.isEmpty())
        m_panels.launch->selectStableKey(place.launchKey);
    if (place.panel != P::Nodes && !place.nodeKey.isEmpty())
        m_panels.nodes->selectStableKey(place.nodeKey);
    switch (place.panel) {
    case P::Nodes:
        showRow(m_panels.nodes, place.key);
        break;
    case P::Launch:
        showRow(m_panels.launch, place.key);
        break;
    case P::Diagram:
        restoreDiagram(place); // the source with the element, which moves it
        break;
    case P::Findings: {
        QTreeView *view = m_panels.log->diagnosticsView();
        const QModelIndexList found =
            view->model()->match(view->model()->index(0, 0), DiagnosticModel::KeyRole, place.key, 1,
                                 Qt::MatchExactly | Qt::MatchRecursive);
        if (!found.isEmpty()) {
            view->selectionModel()->setCurrentIndex(
                found.first(), QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
            view->scrollTo(found.first());
        }
        break;
    }
    case P::Source:
        break;
    }
    if (place.panel != P::Diagram)
        restoreSource(place);
    raisePanel(place.panel);
    endRestoring();
}

void NavigationController::showRow(FilteredTreePanel *panel, const QString &key)
{
    // A row still current is announced again: the views that follow it (the diagram, the
    // inspector, the talkers, the source) may have shown another place since.
    if (panel->currentStableKey() == key)
        Q_EMIT panel->currentSourceIndexChanged(panel->currentSourceIndex());
    else
        panel->selectStableKey(key);
}

void NavigationController::endRestoring()
{
    // Views report some changes a turn of the event loop later (a row made current by a
    // focus change, the source pane's cursor): those still belong to the place shown.
    QTimer::singleShot(0, this, [this, generation = m_restoreGeneration] {
        if (generation == m_restoreGeneration)
            m_restoring = false;
    });
}

void NavigationController::restoreSource(const NavigationPlace &place)
{
    SourceView *source = m_panels.source;
    if (place.sourceFile.isEmpty() || place.sourceLine < 0)
        return;
    if (source->currentFile() != place.sourceFile &&
        !source->showEvidence(Evidence::startOf(place.sourceFile)))
        return;
    source->setPosition(place.sourceLine, place.sourceFirstLine);
}

void NavigationController::restoreDiagram(const NavigationPlace &place)
{
    DiagramPanel *diagram = m_panels.diagram;
    const QString composite = idOf(place.key);
    if (!composite.isEmpty() && diagram->currentComposite() != composite)
        diagram->showComposite(composite);
    if (composite.isEmpty() || place.element.isEmpty() || !diagram->isLayingOut()) {
        restoreElement(place, true);
        return;
    }
    // The element once its composite is drawn, unless the person went on meanwhile (the
    // window stays theirs while a big composite is laid out).
    const int at = m_history->currentIndex();
    m_waitForLayout =
        connect(diagram, &DiagramPanel::layoutFinished, this, [this, place, at](bool ok) {
            disconnect(m_waitForLayout);
            const NavigationPlace *now = m_history->current();
            if (m_history->currentIndex() != at || !now || !now->samePlace(place))
                return;
            m_restoring = true;
            ++m_restoreGeneration;
            restoreElement(place, ok);
            endRestoring();
        });
}

void NavigationController::restoreElement(const NavigationPlace &place, bool drawn)
{
    // Clicked again as the person clicked it: the inspector and the talkers show it too. That
    // moves the source pane to the element's line, so the place's source position comes after.
    if (drawn && !place.element.isEmpty())
        selectDiagramElement(place.element);
    restoreSource(place);
}

void NavigationController::selectDiagramElement(const QString &element)
{
    DiagramPanel *diagram = m_panels.diagram;
    const Composite *c = diagram->architecture().composite(diagram->currentComposite());
    if (!c)
        return;
    if (element.startsWith(kPartPrefix)) {
        const QString instanceKey = element.mid(kPartPrefix.size()).section(u'|', 0, 0);
        const QString portId = element.section(u'|', 1);
        const QString instanceId = idOf(instanceKey);
        for (const RosNodePart &part : c->parts)
            if (!instanceId.isEmpty() && part.instanceId == instanceId) {
                const QString key = portId.isEmpty() || !DiagramBuilder::port(*c, part.id, portId)
                                        ? DiagramBuilder::partKey(part.id)
                                        : DiagramBuilder::portKey(part.id, portId);
                if (diagram->scene()->item(key))
                    diagram->activateElement(key);
                else // inside a collapsed namespace: its box stands for the part
                    diagram->selectInstance(instanceId);
                return;
            }
    } else if (element.startsWith(kChannelPrefix)) {
        const QString name = element.mid(kChannelPrefix.size());
        for (const Channel &ch : c->channels)
            if (channelKindName(ch.kind) + u':' + ch.name == name) {
                diagram->activateElement(DiagramBuilder::channelKey(ch.id));
                return;
            }
    } else if (element.startsWith(kKeyPrefix)) {
        diagram->activateElement(element.mid(kKeyPrefix.size()));
    }
}

void NavigationController::raisePanel(NavigationPlace::Panel panel)
{
    QWidget *widget = panelWidget(m_panels, panel);
    for (QWidget *w = widget; w; w = w->parentWidget())
        if (auto *dock = qobject_cast<QDockWidget *>(w)) {
            dock->show();
            dock->raise();
            break;
        }
}

void NavigationController::updateActions()
{
    m_back->setEnabled(m_history->canGoBack());
    m_forward->setEnabled(m_history->canGoForward());
    const QList<NavigationPlace> places = m_history->places();
    const int at = m_history->currentIndex();
    m_back->setToolTip(m_history->canGoBack()
                           ? tr("Back to %1 (Alt+Left)").arg(describe(places.at(at - 1)))
                           : tr("Back (Alt+Left): nothing visited before"));
    m_forward->setToolTip(m_history->canGoForward()
                              ? tr("Forward to %1 (Alt+Right)").arg(describe(places.at(at + 1)))
                              : tr("Forward (Alt+Right): nothing to go forward to"));
}

QString NavigationController::describe(const NavigationPlace &place) const
{
    switch (place.panel) {
    case NavigationPlace::Panel::Nodes:
        return tr("%1 in the node list").arg(place.label);
    case NavigationPlace::Panel::Launch:
        return tr("%1 in the launch tree").arg(place.label);
    case NavigationPlace::Panel::Diagram:
        return tr("%1 in the diagram").arg(place.label);
    case NavigationPlace::Panel::Source:
        return tr("%1:%2 in the source").arg(place.label).arg(place.sourceLine + 1);
    case NavigationPlace::Panel::Findings:
        return tr("the finding “%1”").arg(place.label);
    }
    return place.label;
}

void NavigationController::onTreeRow(FilteredTreePanel *panel, NavigationPlace::Panel which,
                                     int priority)
{
    NavigationPlace place;
    place.panel = which;
    place.key = panel->currentStableKey();
    place.label = panel->currentSourceIndex().siblingAtColumn(0).data().toString();
    offer(place, priority);
}

void NavigationController::onDiagramElement(const QString &diagramKey)
{
    DiagramPanel *diagram = m_panels.diagram;
    const Composite *c = diagram->architecture().composite(diagram->currentComposite());
    if (!c)
        return;
    NavigationPlace place;
    place.panel = NavigationPlace::Panel::Diagram;
    place.key = keyOf(diagram->currentComposite());
    const DiagramKey k = DiagramKey::parse(diagramKey);
    QString partId = k.id;
    QString portId;
    if (k.kind == DiagramKey::Kind::Port)
        portId = k.portId;
    if (k.kind == DiagramKey::Kind::Connection && k.index() >= 0 &&
        k.index() < c->connections.size())
        partId = c->connections.at(k.index()).partId;
    const bool partLike = k.kind == DiagramKey::Kind::Part || k.kind == DiagramKey::Kind::Port ||
                          k.kind == DiagramKey::Kind::Connection;
    if (const RosNodePart *part = partLike ? c->part(partId) : nullptr) {
        place.element =
            kPartPrefix + keyOf(part->instanceId) + (portId.isEmpty() ? QString() : u'|' + portId);
        place.label = (part->name.isEmpty() ? part->typeName : part->name) +
                      (portId.isEmpty() ? QString() : u' ' + portId);
    } else if (const Channel *ch =
                   k.kind == DiagramKey::Kind::Channel ? c->channel(k.id) : nullptr) {
        place.element = kChannelPrefix + channelKindName(ch->kind) + u':' + ch->name;
        place.label = ch->name;
    } else {
        place.element = kKeyPrefix + diagramKey;
        place.label = diagramKey.section(u':', 1);
    }
    offer(place, kElementPriority);
}

void NavigationController::onCompositeShown(const QString &instanceId)
{
    NavigationPlace place;
    place.panel = NavigationPlace::Panel::Diagram;
    place.key = keyOf(instanceId);
    if (const Composite *c = m_panels.diagram->architecture().composite(instanceId))
        place.label = c->stem;
    offer(place, kCompositePriority);
}

void NavigationController::onFinding()
{
    const QModelIndex current = m_panels.log->diagnosticsView()->currentIndex();
    NavigationPlace place;
    place.panel = NavigationPlace::Panel::Findings;
    place.key = current.data(DiagnosticModel::KeyRole).toString();
    place.label = current.siblingAtColumn(0).data().toString();
    offer(place, kFindingsPriority);
}

void NavigationController::onSourceLine(const QString &file, int line)
{
    NavigationPlace place;
    place.panel = NavigationPlace::Panel::Source;
    place.key = file;
    place.label = file.section(u'/', -1);
    place.sourceLine = line - 1;
    offer(place, kSourcePriority);
}

QString NavigationController::keyOf(const QString &id) const
{
    if (id.isEmpty())
        return {};
    const QString key =
        m_document->session()->keysReady() ? m_document->session()->keyOf(id) : QString();
    return key.isEmpty() ? QStringLiteral("id:") + id : key;
}

QString NavigationController::idOf(const QString &key) const
{
    if (key.startsWith(QLatin1String("id:")))
        return key.mid(3);
    return m_document->session()->keysReady() ? m_document->session()->recoveredKeys().idOf(key)
                                              : QString();
}

} // namespace rosarch
