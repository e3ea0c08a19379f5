#include "app/diagramcontroller.h"
#include "app/appsettings.h"
#include "app/commands/evaluationreport.h"
#include "app/traceability.h"
#include "compose/subsystemgrouping.h"
#include "diagram/rootchoice.h"
#include "document/document.h"
#include "document/nodedescription.h"
#include "evaluation/evaluator.h"
#include "evaluation/recovereddiagrams.h"
#include "jobs/stallprobe.h"
#include "pipeline/recovery.h"
#include "plantuml/umlmodel.h"
#include "project/stablekeys.h"
#include "widgets/diagram/diagrampanel.h"
#include "widgets/launchtreemodel.h"
#include "widgets/launchtreepanel.h"
#include "widgets/logview.h"
#include "widgets/talkerspanel.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QPlainTextEdit>
#include <QScopedValueRollback>
#include <QVBoxLayout>

namespace rosarch {

DiagramController::DiagramController(Document *document, DiagramPanel *panel,
                                     LaunchTreePanel *launchPanel, Traceability *traceability,
                                     TalkersPanel *talkers, LogView *log, QWidget *window)
    : QObject(window), m_document(document), m_panel(panel), m_launchPanel(launchPanel),
      m_traceability(traceability), m_talkers(talkers), m_log(log), m_window(window)
{
    // a node part's tooltip says what its class does, as the inspector does
    m_panel->setDescriber([this](const QString &classId) {
        const NodeDescription d = NodeDescription::of(*m_document, classId);
        if (d.text.isEmpty())
            return d.sourceText();
        // a plain-text tooltip does not wrap: lines of at most about 80 characters
        QStringList lines{QString()};
        for (const QString &word : tr("%1 (%2)").arg(d.text, d.sourceText()).split(u' ')) {
            if (!lines.last().isEmpty() && lines.last().size() + 1 + word.size() > 80)
                lines.append(QString());
            lines.last() += (lines.last().isEmpty() ? QString() : QStringLiteral(" ")) + word;
        }
        return lines.join(u'\n');
    });
    m_exportSvg = new QAction(tr("Export Diagram as &SVG…"), this);
    m_exportSvg->setStatusTip(tr("Write the composed diagram shown as an SVG drawing"));
    connect(m_exportSvg, &QAction::triggered, this,
            [this] { exportDialog(QStringLiteral("svg")); });
    m_exportPng = new QAction(tr("Export Diagram as &PNG…"), this);
    m_exportPng->setStatusTip(tr("Write the composed diagram shown as a PNG image"));
    connect(m_exportPng, &QAction::triggered, this,
            [this] { exportDialog(QStringLiteral("png")); });
    m_compare = new QAction(tr("&Compare with Reference Model…"), this);
    m_compare->setStatusTip(tr("Score the recovered model against hand-written PlantUML "
                               "diagrams and mark the differences in the composed diagram"));
    connect(m_compare, &QAction::triggered, this, &DiagramController::compareDialog);
    m_clearComparison = new QAction(tr("C&lear Comparison"), this);
    connect(m_clearComparison, &QAction::triggered, this, [this] {
        m_evaluation = {};
        m_referencePath.clear();
        applyMarks();
        updateActions();
    });

    connect(m_document, &Document::changed, this, [this](const DocumentChange &change) {
        const StallScope scope("DiagramController (document changed)");
        if (change.parts & (DocumentChange::Model | DocumentChange::Launch))
            onModelReset();
        else if (change.parts & (DocumentChange::Decisions | DocumentChange::Corrections |
                                 DocumentChange::Accepted) &&
                 !m_document->isAcceptedPending()) { // else DocumentChange::Accepted follows
            showArchitecture(); // accepted decisions and corrections change what is drawn
            refreshTalkers();   // and who talks where
        }
    });
    connect(m_launchPanel, &LaunchTreePanel::currentSourceIndexChanged, this,
            [this](const QModelIndex &index) {
                onLaunchItemSelected(index.data(LaunchTreeModel::InstanceIdRole).toString());
            });
    connect(m_panel, &DiagramPanel::partActivated, this, &DiagramController::onPartActivated);
    connect(m_panel, &DiagramPanel::portActivated, this, &DiagramController::onPortActivated);
    connect(m_panel, &DiagramPanel::elementActivated, this, &DiagramController::onElementActivated);
    connect(m_panel, &DiagramPanel::evidenceActivated, m_traceability, &Traceability::showEvidence);
    connect(m_traceability, &Traceability::portSelected, this,
            &DiagramController::onClassPortSelected);
    connect(m_talkers, &TalkersPanel::talkerSelected, this, &DiagramController::onTalkerSelected);
    connect(m_panel, &DiagramPanel::compositeShown, this, &DiagramController::applyMarks);
    connect(m_panel, &DiagramPanel::rootChosen, this, &DiagramController::rememberRoot);
    connect(m_panel, &DiagramPanel::layoutFinished, this, [this](bool ok) {
        if (ok && !m_pendingInstance.isEmpty())
            m_panel->selectInstance(m_pendingInstance);
        m_pendingInstance.clear();
        if (!ok && !m_panel->message().isEmpty())
            m_log->appendLog(tr("Composed diagram: %1").arg(m_panel->message()));
        applyMarks();
    });
    updateActions();
}

namespace {
QString channelFamily(Channel::Kind kind)
{
    return kind == Channel::Kind::Topic     ? QStringLiteral("topic")
           : kind == Channel::Kind::Service ? QStringLiteral("service")
                                            : QStringLiteral("action");
}
} // namespace

void DiagramController::showArchitecture()
{
    Architecture accepted = [this] {
        const StallScope scope("DiagramController accepted model");
        return m_document->accepted().architecture;
    }();
    // A renamed topic, service or action is a person's correction too: drawn as such.
    for (const Correction &c : m_document->session()->corrections()) {
        if (c.kind != Correction::Kind::Rename)
            continue;
        const QString family = StableKeys::family(c.target);
        for (Composite &composite : accepted.composites)
            for (Channel &ch : composite.channels)
                if (channelFamily(ch.kind) == family && ch.name == c.newValue)
                    ch.marks.provenance = Provenance::Corrected;
    }
    if (!m_preview.isEmpty()) // the accepted model with the previewed grouping on top
        accepted = SubsystemGrouping::apply(accepted, m_preview);
    const QList<LaunchRoot> roots = [&] {
        const StallScope scope("DiagramController RootChoice::roots");
        return RootChoice::roots(accepted, m_document->launchDependencies());
    }();
    // Where to start when the composite shown is gone: the project's launch root, else the
    // root a person chose here before, else the one most likely wanted (or ask).
    QString remembered = m_document->session()->launchOptions().rootFile;
    if (remembered.isEmpty() && !m_document->workspaceRoot().isEmpty())
        remembered = AppSettings().diagramRoot(m_document->workspaceRoot());
    const RootChoice start = RootChoice::choose(roots, remembered);
    const StallScope scope("DiagramPanel::setArchitecture");
    m_panel->setArchitecture(accepted, roots, start);
}

void DiagramController::rememberRoot(const QString &instanceId)
{
    const Composite *c = m_panel->architecture().composite(instanceId);
    if (!c || c->file.isEmpty() || m_document->workspaceRoot().isEmpty())
        return;
    AppSettings().setDiagramRoot(m_document->workspaceRoot(), c->file);
}

void DiagramController::previewGrouping(const QString &name, const QStringList &memberIds,
                                        const QString &rootId)
{
    const QList<SubsystemGroup> preview =
        name.isEmpty() ? QList<SubsystemGroup>{} : QList<SubsystemGroup>{{name, memberIds, rootId}};
    if (preview.isEmpty() && m_preview.isEmpty())
        return;
    m_preview = preview;
    showArchitecture();
    if (!memberIds.isEmpty())
        onLaunchItemSelected(memberIds.first());
}

void DiagramController::refreshTalkers()
{
    if (!m_talkersQuery)
        return;
    const QScopedValueRollback guard(m_refreshingTalkers, true);
    const std::function<void()> query = m_talkersQuery;
    m_talkersQuery = {};
    query(); // sets m_talkersQuery again when it still finds its subject
    if (!m_talkersQuery)
        m_talkers->setMessage(tr("What the talkers were listed for changed with the model. Click "
                                 "a topic, service or action in the composed diagram, or a port "
                                 "in the node list, to see who talks on it."));
}

void DiagramController::onModelReset()
{
    m_talkersQuery = {};
    m_preview.clear();
    m_talkers->setMessage(tr("Click a topic, service or action in the composed diagram, or a "
                             "port in the node list, to see who talks on it."));
    showArchitecture();
    if (!m_referencePath.isEmpty()) { // the model changed: score it again
        QString error;
        compareWithReference(m_referencePath, &error);
    }
    updateActions();
}

void DiagramController::onLaunchItemSelected(const QString &instanceId)
{
    if (m_fromDiagram || instanceId.isEmpty())
        return;
    const StallScope scope("DiagramController launch item selected");
    const LaunchDependencies &launch = m_document->launchDependencies();
    QString composite = instanceId;
    if (const NodeInstance *n = launch.node(instanceId))
        composite = n->launchFileId;
    else if (!launch.instance(instanceId))
        return;
    if (composite != m_panel->currentComposite()) {
        m_pendingInstance = instanceId == composite ? QString() : instanceId;
        m_panel->showComposite(composite);
        return;
    }
    if (instanceId != composite)
        m_panel->selectInstance(instanceId);
}

void DiagramController::onPartActivated(const QString &instanceId)
{
    m_fromDiagram = true;
    m_traceability->selectLaunchItem(instanceId);
    m_fromDiagram = false;
}

void DiagramController::onPortActivated(const QString &instanceId, const QString &portId)
{
    // The instance in the launch tree and, for a node's port, the port in the node list; the
    // panel's evidenceActivated (emitted right after) then shows the port's line in code.
    m_fromDiagram = true;
    m_traceability->selectLaunchItem(instanceId);
    if (const NodeInstance *n = m_document->launchDependencies().node(instanceId);
        n && !n->classId.isEmpty())
        m_traceability->selectNode(n->classId, portId);
    m_fromDiagram = false;
}

void DiagramController::onElementActivated(const QString &key)
{
    const auto query = [this, key] { onElementActivated(key); };
    const Architecture &architecture = m_panel->architecture();
    const QString scope = m_panel->currentComposite();
    const Composite *c = architecture.composite(scope);
    if (!c)
        return;
    const DiagramKey k = DiagramKey::parse(key);
    switch (k.kind) {
    case DiagramKey::Kind::Channel:
        if (const Channel *channel = c->channel(k.id)) {
            const QString family = channelKindName(channel->kind);
            showTalkers(tr("%1 %2").arg(family, channel->name), scope,
                        {TalkerSearch::find(architecture, scope, family, channel->name)});
            m_talkersQuery = query;
        }
        break;
    case DiagramKey::Kind::Boundary:
        if (const BoundaryPort *b = c->boundaryPort(k.id)) {
            const QString family = portFamilyName(b->kind);
            showTalkers(tr("%1 %2").arg(family, b->name), scope,
                        {TalkerSearch::find(architecture, scope, family, b->name)});
            m_talkersQuery = query;
        }
        break;
    case DiagramKey::Kind::Port:
    case DiagramKey::Kind::Connection: {
        QString partId = k.id;
        QString portId = k.portId;
        if (k.kind == DiagramKey::Kind::Connection) {
            if (k.index() < 0 || k.index() >= c->connections.size())
                return;
            partId = c->connections.at(k.index()).partId;
            portId = c->connections.at(k.index()).portId;
        }
        const TalkerGroup group = TalkerSearch::ofPartPort(architecture, scope, partId, portId);
        if (!group.name.isEmpty()) {
            showTalkers(tr("%1 %2").arg(group.family, group.name), scope, {group});
            m_talkersQuery = query;
        }
        break;
    }
    default:
        break;
    }
}

void DiagramController::onClassPortSelected(const QString &classId, const QString &portId)
{
    if (m_fromDiagram || m_fromTalkers)
        return; // the diagram click or the talker chosen says more precisely what to show
    const Architecture &architecture = m_panel->architecture();
    const QString scope =
        TalkerSearch::scopeOfClass(architecture, m_panel->currentComposite(), classId);
    const AtomicNode *node = m_document->atomicNodes().node(classId);
    const QString className = node ? node->className : classId;
    const QString subject = tr("port %1 of %2").arg(portId, className);
    if (scope.isEmpty()) {
        m_talkers->setMessage(
            tr("No launch file starts %1, so its port %2 talks on nothing in the composed "
               "architecture.")
                .arg(className, portId));
        return;
    }
    showTalkers(subject, scope, TalkerSearch::ofClassPort(architecture, scope, classId, portId));
    m_talkersQuery = [this, classId, portId] { onClassPortSelected(classId, portId); };
}

void DiagramController::showTalkers(const QString &subject, const QString &scopeId,
                                    const QList<TalkerGroup> &groups)
{
    const Composite *c = m_panel->architecture().composite(scopeId);
    // A name on the composite's boundary goes on outside it: say so, rather than suggest
    // that the talkers listed are all there are.
    QStringList leaving;
    for (const TalkerGroup &g : groups)
        for (const BoundaryPort &b : c ? c->boundary : QList<BoundaryPort>())
            if (b.name == g.name && portFamilyName(b.kind) == g.family && !leaving.contains(g.name))
                leaving << g.name;
    const QString note =
        leaving.isEmpty() || !c || c->parentId.isEmpty()
            ? QString()
            : tr("%1 leaves %2 through its boundary: the launch files that include %2 may "
                 "have more talkers.")
                  .arg(leaving.join(QStringLiteral(", ")), c->stem);
    m_talkers->showTalkers(subject, c ? c->stem : scopeId, groups, note);
    if (!m_refreshingTalkers)
        Q_EMIT talkersShown();
}

void DiagramController::onTalkerSelected(const QString &instanceId, const QString &portId)
{
    // The instance in the launch tree (the node list follows with its class) and in the
    // diagram, then its port in the node list and the port's line in code; the talkers stay.
    const QScopedValueRollback guard(m_fromTalkers, true);
    m_traceability->selectLaunchItem(instanceId);
    onLaunchItemSelected(instanceId); // also when the launch tree was already there
    const NodeInstance *n = m_document->launchDependencies().node(instanceId);
    if (!n || n->classId.isEmpty())
        return;
    m_traceability->selectNode(n->classId, portId);
    for (const Composite &c : m_panel->architecture().composites)
        for (const RosNodePart &part : c.parts)
            if (part.instanceId == instanceId)
                if (const PartPort *port = DiagramBuilder::port(c, part.id, portId);
                    port && port->evidence.isValid()) {
                    m_traceability->showEvidence(port->evidence);
                    return;
                }
}

void DiagramController::applyMarks()
{
    const Composite *c = m_document->accepted().architecture.composite(m_panel->currentComposite());
    const LevelEvaluation *ccd = m_evaluation.level(UmlLevel::Ccd);
    if (!c || !ccd) {
        m_panel->setMarks({});
        return;
    }
    const DiagramEvaluation *d = ccd->diagram(c->stem);
    if (!d) {
        m_panel->setMarks({}, {tr("the reference has no diagram for %1").arg(c->stem)});
        return;
    }
    // Recovered elements carry the key of what the diagram draws for them (recoveredDiagrams).
    QHash<QString, DiagramMark> marks;
    QStringList missing;
    for (const KindEvaluation &k : d->kinds) {
        for (const UmlElement &e : k.falsePositives)
            if (!e.key.isEmpty())
                marks.insert(e.key, DiagramMark::Extra);
        for (const UmlElement &e : k.falseNegatives)
            missing << QStringLiteral("%1 %2").arg(umlKindLabel(e.kind), e.value);
    }
    m_panel->setMarks(marks, missing);
}

QString DiagramController::compareWithReference(const QString &path, QString *error)
{
    UmlModel reference;
    if (!UmlModel::load(path, &reference, error))
        return {};
    const Recovery &accepted = m_document->accepted();
    const QList<UmlDiagram> recovered = recoveredDiagrams(accepted.nodes, accepted.architecture);
    QList<UmlLevel> levels;
    for (UmlLevel l : {UmlLevel::Acd, UmlLevel::Ccd})
        if (reference.hasLevel(l))
            levels << l;
    if (levels.isEmpty()) {
        *error =
            tr("No ACD or CCD diagram could be read in %1.").arg(QDir::toNativeSeparators(path));
        return {};
    }
    m_evaluation = Evaluator::evaluate(
        reference.ofLevel(UmlLevel::Acd) + reference.ofLevel(UmlLevel::Ccd), recovered, levels);
    m_referencePath = path;
    QString text;
    for (const LevelEvaluation &l : m_evaluation.levels) {
        int count = 0;
        for (const UmlDiagram &d : recovered)
            count += d.level == l.level ? 1 : 0;
        text += EvaluationReport::levelText(l, count);
        m_log->appendLog(tr("Compared with %1 (%2): micro F1 %3, macro F1 %4")
                             .arg(QDir::toNativeSeparators(path), umlLevelName(l.level).toUpper())
                             .arg(l.micro.f1, 0, 'f', 3)
                             .arg(l.macro.f1, 0, 'f', 3));
    }
    for (const UmlDiagram &d : reference.diagrams)
        for (const QString &n : d.notes)
            text += QStringLiteral("%1: %2\n").arg(d.file, n);
    applyMarks();
    updateActions();
    return text;
}

void DiagramController::compareDialog()
{
    AppSettings settings;
    const QString start = m_referencePath.isEmpty() ? settings.lastExportFolder() : m_referencePath;
    const QString path = QFileDialog::getExistingDirectory(
        m_window, tr("Reference Model (folder of PlantUML diagrams)"), start);
    if (path.isEmpty())
        return;
    QString error;
    const QString report = compareWithReference(path, &error);
    if (report.isEmpty()) {
        m_log->appendLog(tr("Comparison failed: %1").arg(error));
        Q_EMIT statusMessage(error, 8000);
        return;
    }
    auto *dialog = new QDialog(m_window);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(tr("Comparison with %1").arg(QDir::toNativeSeparators(path)));
    auto *layout = new QVBoxLayout(dialog);
    auto *text = new QPlainTextEdit(report, dialog);
    text->setReadOnly(true);
    text->setLineWrapMode(QPlainTextEdit::NoWrap);
    text->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    layout->addWidget(text);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    layout->addWidget(buttons);
    dialog->resize(900, 600);
    dialog->open();
}

bool DiagramController::exportDiagram(const QString &path)
{
    const bool svg = path.endsWith(QLatin1String(".svg"), Qt::CaseInsensitive);
    const bool ok = svg ? m_panel->exportSvg(path) : m_panel->exportPng(path);
    const QString where = QDir::toNativeSeparators(path);
    m_log->appendLog(ok ? tr("Exported the composed diagram to %1").arg(where)
                        : tr("Could not write the composed diagram to %1").arg(where));
    Q_EMIT statusMessage(ok ? tr("Exported %1").arg(where) : tr("Export failed: %1").arg(where),
                         5000);
    return ok;
}

void DiagramController::exportDialog(const QString &suffix)
{
    AppSettings settings;
    const Composite *c = m_document->architecture().composite(m_panel->currentComposite());
    const QString name = (c ? c->stem : QStringLiteral("diagram")) + QLatin1Char('.') + suffix;
    const QString start =
        QDir(settings.lastExportFolder().isEmpty() ? QDir::homePath() : settings.lastExportFolder())
            .filePath(name);
    const QString filter =
        suffix == QLatin1String("svg") ? tr("SVG drawing (*.svg)") : tr("PNG image (*.png)");
    QString path =
        QFileDialog::getSaveFileName(m_window, tr("Export Composed Diagram"), start, filter);
    if (path.isEmpty())
        return;
    if (QFileInfo(path).suffix().isEmpty())
        path += QLatin1Char('.') + suffix;
    settings.setLastExportFolder(QFileInfo(path).path());
    exportDiagram(path);
}

void DiagramController::updateActions()
{
    const bool drawn = !m_document->architecture().composites.isEmpty();
    m_exportSvg->setEnabled(drawn);
    m_exportPng->setEnabled(drawn);
    m_compare->setEnabled(!m_document->workspaceRoot().isEmpty());
    m_clearComparison->setEnabled(!m_evaluation.levels.isEmpty());
}

} // namespace rosarch
