#include "app/correctioncontroller.h"
#include "app/correctioneditor.h"
#include "app/correctionlookup.h"
#include "app/correctiontargets.h"
#include "app/inspectorpresenter.h"
#include "app/traceability.h"
#include "diagram/diagrambuilder.h"
#include "document/document.h"
#include "widgets/atomicnodepanel.h"
#include "widgets/correctionpanel.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/diagram/diagramview.h"
#include "widgets/launchtreepanel.h"

#include <QAction>
#include <QMenu>
#include <QTreeView>

#include <functional>

namespace rosarch {

namespace {

using Kind = CorrectionController::Element::Kind;
using namespace CorrectionLookup;

} // namespace

CorrectionController::CorrectionController(Document *document, AtomicNodePanel *nodePanel,
                                           LaunchTreePanel *launchPanel, DiagramPanel *diagramPanel,
                                           Traceability *traceability, InspectorPanel *inspector,
                                           CorrectionPanel *corrections, QWidget *window)
    : QObject(window), m_document(document), m_nodePanel(nodePanel), m_launchPanel(launchPanel),
      m_diagramPanel(diagramPanel), m_traceability(traceability),
      m_targets(new CorrectionTargets(document, this)),
      m_editor(new CorrectionEditor(document, m_targets, window, this)),
      m_presenter(new InspectorPresenter(document, m_targets, nodePanel, launchPanel, diagramPanel,
                                         inspector, this))
{
    m_presenter->setActions(
        [this](const Element &element, QObject *parent) { return actionsFor(element, parent); });
    connect(m_editor, &CorrectionEditor::statusMessage, this, &CorrectionController::statusMessage);
    connect(nodePanel, &AtomicNodePanel::contextMenuRequested, this,
            [this](QMenu *menu, const QModelIndex &index) {
                addMenuActions(menu, m_presenter->nodeElement(index));
            });
    connect(nodePanel, &AtomicNodePanel::renameRequested, this, [this](const QModelIndex &index) {
        m_editor->rename(m_presenter->nodeElement(index));
    });
    connect(launchPanel, &LaunchTreePanel::contextMenuRequested, this,
            [this](QMenu *menu, const QModelIndex &index) {
                addMenuActions(menu, m_presenter->launchElement(index));
            });
    connect(diagramPanel, &DiagramPanel::elementMenuRequested, this,
            [this](const QString &key, QMenu *menu) {
                const Element e = m_presenter->diagramElement(key);
                addMenuActions(menu, e);
                // several parts of one root: a subsystem
                QStringList ids;
                for (const QString &k : m_diagramPanel->selectedKeys() + QStringList{key}) {
                    const Element part = m_presenter->diagramElement(k);
                    if (part.kind == Kind::Instance && !ids.contains(part.id) &&
                        part.rootId == e.rootId)
                        ids.append(part.id);
                }
                if (e.kind == Kind::Instance && ids.size() >= 2) {
                    menu->addSeparator();
                    QAction *g = menu->addAction(tr("&Group Selected Parts into Subsystem\u2026"));
                    connect(g, &QAction::triggered, this,
                            [this, ids, root = e.rootId] { m_editor->group(ids, root); });
                }
            });
    connect(corrections, &CorrectionPanel::correctionActivated, this,
            &CorrectionController::showCorrection);
    connect(corrections, &CorrectionPanel::removeRequested, m_editor,
            &CorrectionEditor::removeCorrections);
    connect(corrections, &CorrectionPanel::retargetRequested, m_editor,
            &CorrectionEditor::retarget);
    installShortcuts();
    m_presenter->refreshInspector();
}

const CorrectionController::Element &CorrectionController::current() const
{
    return m_presenter->current();
}

QList<QAction *> CorrectionController::actionsFor(const Element &e, QObject *parent)
{
    QList<QAction *> actions;
    const auto add = [&](const QString &text, const QKeySequence &shortcut, auto fn) {
        auto *a = new QAction(text, parent);
        if (!shortcut.isEmpty()) {
            a->setShortcut(shortcut);
            a->setShortcutContext(Qt::WidgetShortcut); // shown; the views own the keys
        }
        connect(a, &QAction::triggered, this, [e, fn] { fn(e); });
        actions.append(a);
        return a;
    };
    if (e.kind == Kind::None || m_presenter->describe(e).kind.isEmpty())
        return actions;
    if (m_targets->isRemoved(e)) {
        add(tr("Restore (Revert %1)").arg(m_targets->index().removedBy(e.id)), {},
            [this](const Element &x) { m_editor->restore(x); });
        return actions;
    }
    const QKeySequence review(tr("Ctrl+R"));
    const QString reviewText =
        m_presenter->describe(e).reviewed ? tr("Unmark Reviewed") : tr("Mark Re&viewed");
    switch (e.kind) {
    case Kind::Class:
        add(tr("Add &Port\u2026"), {}, [this](const Element &x) { m_editor->addPort(x); });
        add(tr("Re&move Class\u2026"), QKeySequence::Delete,
            [this](const Element &x) { m_editor->remove(x); });
        break;
    case Kind::Port: {
        const Port *p = findPort(m_document->accepted().nodes, e.id);
        const bool expression = p && !p->isResolved();
        add(expression ? tr("Set &Name\u2026") : tr("Re&name\u2026"), Qt::Key_F2,
            [this](const Element &x) { m_editor->rename(x); });
        QAction *type =
            add(tr("Set &Type\u2026"), {}, [this](const Element &x) { m_editor->setType(x); });
        if (p && !isCanonicalInterfaceType(p->type))
            type->setText(tr("Set &Type\u2026 (unknown)"));
        add(tr("Re&move Port\u2026"), QKeySequence::Delete,
            [this](const Element &x) { m_editor->remove(x); });
        break;
    }
    case Kind::Instance:
        add(tr("Re&name\u2026"), Qt::Key_F2, [this](const Element &x) { m_editor->rename(x); });
        add(tr("Re&move\u2026"), QKeySequence::Delete,
            [this](const Element &x) { m_editor->remove(x); });
        add(tr("Add &Connection\u2026"), {},
            [this](const Element &x) { m_editor->addConnection(x); });
        break;
    case Kind::LaunchFile:
        add(tr("Add &Part\u2026"), {}, [this](const Element &x) { m_editor->addPart(x); });
        return actions; // a launch file is not reviewed on its own
    case Kind::Channel:
        add(tr("Re&name\u2026"), Qt::Key_F2, [this](const Element &x) { m_editor->rename(x); });
        break;
    case Kind::Connection:
        if (!m_targets->keysAtHand(e.port) || !m_targets->keyOf(e.port).isEmpty())
            add(tr("Remove &Connection\u2026"), QKeySequence::Delete,
                [this](const Element &x) { m_editor->remove(x); });
        return actions;
    case Kind::None:
        break;
    }
    add(reviewText, review, [this](const Element &x) { m_editor->toggleReviewed(x); });
    return actions;
}

void CorrectionController::addMenuActions(QMenu *menu, const Element &element)
{
    const QList<QAction *> actions = actionsFor(element, menu);
    if (actions.isEmpty())
        return;
    menu->addSection(tr("Correct"));
    menu->addActions(actions);
}

void CorrectionController::showCorrection(const QString &id)
{
    const Correction *c = m_document->session()->correction(id);
    if (!c)
        return;
    const QString family = StableKeys::family(c->target);
    QString elementId = m_targets->index().idOf(c->target);
    if (c->kind == Correction::Kind::AddPart) // the part it added, in its first launch file
        for (const NodeInstance &n : m_document->accepted().launch.nodes)
            if (n.id.startsWith(c->id + u'_')) {
                elementId = n.id;
                break;
            }
    if (family == QLatin1String("launch"))
        for (const LaunchFileInstance &lf : m_document->accepted().launch.instances)
            if (StableKeys::launchKey(lf) == c->target && elementId.isEmpty())
                elementId = lf.id;
    if (StableKeys::isChannelKey(c->target)) {
        QString name = c->target.section(u':', 1);
        if (c->kind == Correction::Kind::Rename)
            name = c->newValue;
        const Element e{Kind::Channel, family + u':' + name, {}, {}};
        if (const Composite *shown =
                m_diagramPanel->architecture().composite(m_diagramPanel->currentComposite()))
            for (const Channel &ch : shown->channels)
                if (channelFamily(ch.kind) == family && ch.name == name)
                    m_diagramPanel->selectElement(DiagramBuilder::channelKey(ch.id));
        m_presenter->setCurrent(e);
        return;
    }
    if (elementId.isEmpty())
        return; // orphaned: nothing to show
    if (family == QLatin1String("class")) {
        m_traceability->selectNode(elementId);
    } else if (family == QLatin1String("port")) {
        m_traceability->selectNode(elementId.section(u'/', 0, 0), elementId.section(u'/', 1));
    } else {
        m_traceability->selectLaunchItem(elementId);
        m_diagramPanel->selectInstance(elementId);
    }
}

void CorrectionController::installShortcuts()
{
    // The keys act on the view that has the focus: F2 renames, Delete removes, Ctrl+R marks
    // reviewed. The node list keeps F2 for a class's description (AtomicNodePanel).
    const auto install = [this](QWidget *view, std::function<Element()> current, bool f2) {
        const auto make = [&](const QKeySequence &keys, auto fn) {
            auto *a = new QAction(view);
            a->setShortcut(keys);
            a->setShortcutContext(Qt::WidgetShortcut);
            connect(a, &QAction::triggered, this, [current, fn] { fn(current()); });
            view->addAction(a);
        };
        if (f2)
            make(Qt::Key_F2, [this](const Element &e) { m_editor->rename(e); });
        make(QKeySequence::Delete, [this](const Element &e) { m_editor->remove(e); });
        make(QKeySequence(tr("Ctrl+R")), [this](const Element &e) { m_editor->toggleReviewed(e); });
    };
    install(
        m_nodePanel->treeView(),
        [this] { return m_presenter->nodeElement(m_nodePanel->currentSourceIndex()); }, false);
    install(
        m_launchPanel->treeView(),
        [this] { return m_presenter->launchElement(m_launchPanel->currentSourceIndex()); }, true);
    install(
        m_diagramPanel->view(),
        [this] {
            const QStringList keys = m_diagramPanel->selectedKeys();
            return keys.isEmpty() ? Element{} : m_presenter->diagramElement(keys.first());
        },
        true);
}

} // namespace rosarch
