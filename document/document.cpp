#include "document.h"
#include "correctioncommand.h"
#include "decidesuggestioncommand.h"
#include "decisionstore.h"
#include "project.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSet>

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent)
{
    m_autosave.setSingleShot(true);
    m_autosave.setInterval(2000);
    connect(&m_autosave, &QTimer::timeout, this, [this] { writeAutosave(); });
    connect(&m_undoStack, &QUndoStack::cleanChanged, this, [this] { updateModified(); });
}

Document::~Document()
{
    writeAutosave(); // not a save: the next open offers to recover it
}

void Document::emitChange(DocumentChange::Parts parts, const QString &id)
{
    Q_EMIT changed(DocumentChange{parts, id});
}

void Document::setRecovery(Recovery recovery)
{
    // A re-run of the same workspace keeps the project in memory, modified or not; another
    // workspace's project replaces it, its changes kept in the autosave side file first.
    const bool sameWorkspace = recovery.nodes.workspaceRoot == workspaceRoot();
    const QList<SuggestionDecision> keyed = keyedDecisions(); // by the keys of the old model
    const QList<Suggestion> suggestions = sameWorkspace ? keyedSuggestions() : QList<Suggestion>{};
    const bool modified = isModified();
    if (!sameWorkspace)
        writeAutosave();
    const LaunchOptions optionsBefore = m_launchOptions;
    DocumentChange change{DocumentChange::Model | DocumentChange::Decisions, {}};
    if (hasSuggestionReport())
        change.parts |= DocumentChange::Suggestions;
    Q_EMIT aboutToChange(change);
    m_corrected.reset();
    m_keys.reset();
    m_modifiedOutside = sameWorkspace && modified; // undo history goes, the changes stay
    m_undoStack.clear();
    m_nodes = std::move(recovery.nodes);
    m_launch = std::move(recovery.launch);
    m_architecture = std::move(recovery.architecture);
    m_analysisDescriptions.clear();
    for (const AtomicNode &n : m_nodes.nodes)
        m_analysisDescriptions.insert(n.id, n.description);
    if (sameWorkspace && !m_migrationPending) {
        bindDecisions(keyed); // re-bound from memory, by key
    } else {
        if (m_chosenProject && m_chosenProject->first != workspaceRoot())
            m_chosenProject.reset(); // that project belongs to another workspace
        loadDecisions();
    }
    if (m_launchOptions != optionsBefore)
        change.parts |= DocumentChange::LaunchOptions;
    // The suggestions were made on the old model: they stay, by key, where their subject is
    // still there (its id may be another now), and go where it is gone.
    if (sameWorkspace)
        bindSuggestions(suggestions);
    else
        clearSuggestions();
    updateModified();
    Q_EMIT changed(change);
}

void Document::setAtomicNodes(AtomicNodeList nodes)
{
    setRecovery({std::move(nodes), {}, {}});
}

void Document::setLaunchDependencies(LaunchDependencies launch, Architecture architecture)
{
    DocumentChange change{DocumentChange::Launch | DocumentChange::Decisions, {}};
    if (hasSuggestionReport())
        change.parts |= DocumentChange::Suggestions;
    Q_EMIT aboutToChange(change);
    m_corrected.reset();
    const QList<SuggestionDecision> keyed = keyedDecisions(); // launch ids may change
    const QList<Suggestion> suggestions = keyedSuggestions();
    m_keys.reset();
    m_launch = std::move(launch);
    m_architecture = std::move(architecture);
    bindDecisions(keyed);
    bindSuggestions(suggestions); // by key: groupings and names refer to launch ids
    Q_EMIT changed(change);
}

void Document::setLaunchOptions(const LaunchOptions &options)
{
    if (options == m_launchOptions)
        return;
    m_launchOptions = options;
    m_modifiedOutside = true; // not an undo step
    markDecisionsChanged();
    emitChange(DocumentChange::LaunchOptions);
}

void Document::adoptLaunchOptions(const LaunchOptions &options)
{
    if (options == m_launchOptions)
        return;
    m_launchOptions = options;
    emitChange(DocumentChange::LaunchOptions);
}

void Document::setNodeDescription(const QString &nodeId, const QString &description)
{
    const AtomicNode *node = m_nodes.node(nodeId);
    if (!node || node->description == description)
        return;
    // a correction like any other: kept in the project by key, so a re-run keeps it
    Correction c;
    c.kind = Correction::Kind::Describe;
    c.target = keyOf(nodeId);
    c.oldValue = node->description;
    c.newValue = description;
    addCorrection(c);
}

QStringList Document::refreshDescriptions()
{
    // as analysis found them, then accepted suggestions, then a person's own edits in order
    QHash<QString, QString> wanted = m_analysisDescriptions;
    for (const SuggestionDecision &d : std::as_const(m_decisions))
        if (d.kind == Suggestion::Kind::NodeDescription &&
            d.status == Suggestion::Status::Accepted && wanted.contains(d.targetId))
            wanted.insert(d.targetId, d.proposal);
    bool anyEdit = false;
    for (const Correction &c : std::as_const(m_project.corrections))
        anyEdit = anyEdit || c.kind == Correction::Kind::Describe;
    if (anyEdit) {
        QHash<QString, QString> idOfKey;
        for (const AtomicNode &n : std::as_const(m_nodes.nodes))
            idOfKey.insert(keyOf(n.id), n.id);
        for (const Correction &c : std::as_const(m_project.corrections))
            if (c.kind == Correction::Kind::Describe && idOfKey.contains(c.target))
                wanted.insert(idOfKey.value(c.target), c.newValue);
    }
    QStringList changed;
    for (AtomicNode &n : m_nodes.nodes)
        if (const auto it = wanted.constFind(n.id); it != wanted.cend() && n.description != *it) {
            n.description = *it;
            changed << n.id;
        }
    return changed;
}

const Suggestion *Document::suggestion(const QString &id) const
{
    for (const Suggestion &s : m_suggestionReport.suggestions)
        if (s.id == id)
            return &s;
    return nullptr;
}

int Document::setSuggestions(SuggestionReport report)
{
    Q_EMIT aboutToChange({DocumentChange::Suggestions, {}});
    int decidedBefore = 0;
    QStringList changedNodes;
    for (Suggestion &s : report.suggestions) {
        const auto it = m_decisions.constFind(SuggestionDecision::keyOf(s));
        s.status = it == m_decisions.cend() ? Suggestion::Status::Pending : it->status;
        if (it == m_decisions.cend())
            continue;
        ++decidedBefore;
        if (s.status == Suggestion::Status::Accepted &&
            s.kind == Suggestion::Kind::NodeDescription) {
            for (AtomicNode &n : m_nodes.nodes)
                if (n.id == s.targetId && n.description != s.value) {
                    n.description = s.value;
                    changedNodes << n.id;
                }
        }
    }
    m_suggestionReport = std::move(report);
    if (!changedNodes.isEmpty())
        m_corrected.reset();
    emitChange(DocumentChange::Suggestions);
    for (const QString &id : std::as_const(changedNodes))
        emitChange(DocumentChange::Node, id);
    return decidedBefore;
}

bool Document::hasSuggestionReport() const
{
    const SuggestionReport &r = m_suggestionReport;
    return !r.suggestions.isEmpty() || !r.prompts.isEmpty() || !r.errors.isEmpty() ||
           !r.discarded.isEmpty();
}

bool Document::clearSuggestions()
{
    if (!hasSuggestionReport())
        return false;
    m_suggestionReport = {};
    return true;
}

bool Document::acceptSuggestion(const QString &id)
{
    const Suggestion *s = suggestion(id);
    if (!s || s->status == Suggestion::Status::Accepted)
        return false;
    m_undoStack.push(new DecideSuggestionCommand(this, *s, Suggestion::Status::Accepted));
    return true;
}

bool Document::rejectSuggestion(const QString &id)
{
    const Suggestion *s = suggestion(id);
    if (!s || s->status == Suggestion::Status::Rejected)
        return false;
    m_undoStack.push(new DecideSuggestionCommand(this, *s, Suggestion::Status::Rejected));
    return true;
}

int Document::acceptAllSuggestions(Suggestion::Kind kind)
{
    QList<const Suggestion *> pending;
    QSet<QString> keys;
    for (const Suggestion &s : m_suggestionReport.suggestions)
        if (s.kind == kind && s.status == Suggestion::Status::Pending &&
            !keys.contains(SuggestionDecision::keyOf(s))) {
            keys.insert(SuggestionDecision::keyOf(s));
            pending << &s;
        }
    if (pending.isEmpty())
        return 0;
    // One parent command: the whole batch is one undo step.
    auto *macro =
        new QUndoCommand(QCoreApplication::translate("rosarch::Document", "Accept %1 suggestions")
                             .arg(pending.size()));
    for (const Suggestion *s : pending)
        new DecideSuggestionCommand(this, *s, Suggestion::Status::Accepted, macro);
    m_undoStack.push(macro);
    return int(pending.size());
}

QList<SubsystemGroup> Document::acceptedGroupings() const
{
    return AcceptedModel::select(m_decisions, {m_nodes, m_launch, m_architecture}).groupings;
}

QMap<QString, QString> Document::acceptedNames() const
{
    return AcceptedModel::select(m_decisions, {m_nodes, m_launch, m_architecture}).names;
}

const Recovery &Document::accepted() const
{
    if (!m_corrected) {
        // The model as analysis found it: the nodes here hold the descriptions accepted or
        // edited since, which the project applies itself (the same function as every export
        // and the command line).
        Recovery recovered{m_nodes, m_launch, m_architecture};
        for (AtomicNode &n : recovered.nodes.nodes)
            n.description = m_analysisDescriptions.value(n.id, n.description);
        m_corrected = CorrectedModel::apply(recovered, project());
    }
    return m_corrected->recovery;
}

const QList<Orphan> &Document::orphans() const
{
    accepted();
    return m_corrected->orphans;
}

QList<SuggestionDecision> Document::keyedDecisions() const
{
    QList<SuggestionDecision> out = m_unboundDecisions;
    const StableKeys keys(Recovery{m_nodes, m_launch, m_architecture});
    for (const SuggestionDecision &d : m_decisions) {
        SuggestionDecision k;
        if (CorrectedModel::keyed(d, keys, &k))
            out.append(k);
    }
    return out;
}

void Document::bindDecisions(const QList<SuggestionDecision> &keyed)
{
    m_decisions.clear();
    m_unboundDecisions.clear();
    const StableKeys keys(Recovery{m_nodes, m_launch, m_architecture});
    for (const SuggestionDecision &d : keyed) {
        SuggestionDecision b;
        QString reason;
        if (CorrectedModel::bound(d, keys, &b, &reason))
            m_decisions.insert(b.key(), b);
        else
            m_unboundDecisions.append(d); // kept, applied to nothing
    }
    m_corrected.reset();
    applyStoredDescriptions();
}

Project Document::project() const
{
    Project p = m_project;
    p.launch = m_launchOptions;
    p.workspace = m_projectPath.isEmpty()
                      ? QString()
                      : ProjectFile::workspaceField(m_projectPath, workspaceRoot());
    p.decisions = keyedDecisions();
    std::sort(p.decisions.begin(), p.decisions.end(),
              [](const auto &a, const auto &b) { return a.key() < b.key(); });
    return p;
}

QString Document::keyOf(const QString &id) const
{
    if (!m_keys)
        m_keys = StableKeys(Recovery{m_nodes, m_launch, m_architecture});
    return m_keys->keyOf(id);
}

QList<Suggestion> Document::keyedSuggestions() const
{
    QList<Suggestion> out;
    for (Suggestion s : m_suggestionReport.suggestions) {
        s.targetId = keyOf(s.targetId);
        bool known = !s.targetId.isEmpty();
        for (QString &m : s.memberIds) {
            m = keyOf(m);
            known = known && !m.isEmpty();
        }
        if (known)
            out.append(s);
    }
    return out;
}

void Document::bindSuggestions(const QList<Suggestion> &keyed)
{
    if (!m_keys)
        m_keys = StableKeys(Recovery{m_nodes, m_launch, m_architecture});
    QList<Suggestion> bound;
    for (Suggestion s : keyed) {
        s.targetId = m_keys->idOf(s.targetId);
        bool there = !s.targetId.isEmpty();
        for (QString &m : s.memberIds) {
            m = m_keys->idOf(m);
            there = there && !m.isEmpty();
        }
        if (!there)
            continue; // its subject is gone
        s.memberIds.sort();
        const auto it = m_decisions.constFind(SuggestionDecision::keyOf(s));
        s.status = it == m_decisions.cend() ? Suggestion::Status::Pending : it->status;
        bound.append(s);
    }
    m_suggestionReport.suggestions = bound;
}

QString Document::author()
{
    const QString configured = qEnvironmentVariable("ROSARCH_AUTHOR");
    if (!configured.isEmpty())
        return configured;
    const QString user = qEnvironmentVariable("USER", qEnvironmentVariable("USERNAME"));
    return user.isEmpty() ? QStringLiteral("unknown") : user;
}

bool Document::prepare(Correction *correction, int offset) const
{
    if (correction->target.isEmpty() || StableKeys::family(correction->target).isEmpty())
        return false;
    if (correction->id.isEmpty()) {
        Project p;
        p.corrections = m_project.corrections;
        QString id = p.nextCorrectionId();
        id = QStringLiteral("c%1").arg(id.mid(1).toInt() + offset);
        correction->id = id;
    }
    if (correction->author.isEmpty())
        correction->author = author();
    if (!correction->time.isValid())
        correction->time = QDateTime::currentDateTimeUtc();
    correction->time = correction->time.toUTC();
    correction->time.setTime(QTime(correction->time.time().hour(), correction->time.time().minute(),
                                   correction->time.time().second())); // ISO 8601 seconds
    return true;
}

QString Document::addCorrection(Correction correction)
{
    if (!prepare(&correction, 0))
        return {};
    const QString id = correction.id;
    m_undoStack.push(new CorrectionCommand(this, CorrectionCommand::Action::Add, correction,
                                           int(m_project.corrections.size())));
    return id;
}

QStringList Document::addCorrections(const QList<Correction> &corrections, const QString &text)
{
    QStringList ids;
    auto *macro = new QUndoCommand(text);
    int index = int(m_project.corrections.size());
    for (Correction c : corrections) {
        if (!prepare(&c, int(ids.size())))
            continue;
        ids << c.id;
        new CorrectionCommand(this, CorrectionCommand::Action::Add, c, index++, macro);
    }
    if (ids.isEmpty()) {
        delete macro;
        return ids;
    }
    m_undoStack.push(macro);
    return ids;
}

bool Document::removeCorrection(const QString &id)
{
    for (int i = 0; i < m_project.corrections.size(); ++i)
        if (m_project.corrections.at(i).id == id) {
            m_undoStack.push(new CorrectionCommand(this, CorrectionCommand::Action::Remove,
                                                   m_project.corrections.at(i), i));
            return true;
        }
    return false;
}

void Document::insertCorrection(int index, const Correction &correction)
{
    m_project.corrections.insert(std::clamp(index, 0, int(m_project.corrections.size())),
                                 correction);
    m_corrected.reset();
    markDecisionsChanged();
    const QStringList described = refreshDescriptions(); // before the views read them
    emitChange(DocumentChange::Corrections, correction.id);
    for (const QString &id : described)
        emitChange(DocumentChange::Node, id);
}

void Document::takeCorrection(const QString &id)
{
    m_project.corrections.removeIf([&](const Correction &c) { return c.id == id; });
    m_corrected.reset();
    markDecisionsChanged();
    const QStringList described = refreshDescriptions(); // before the views read them
    emitChange(DocumentChange::Corrections, id);
    for (const QString &node : described)
        emitChange(DocumentChange::Node, node);
}

QString Document::decisionsPath() const
{
    return m_projectPath;
}

Document::DecisionSnapshot Document::snapshot(const Suggestion &suggestion) const
{
    DecisionSnapshot snap;
    snap.key = SuggestionDecision::keyOf(suggestion);
    if (const auto it = m_decisions.constFind(snap.key); it != m_decisions.cend())
        snap.decision = *it;
    if (suggestion.kind == Suggestion::Kind::NodeDescription) {
        if (const AtomicNode *n = m_nodes.node(suggestion.targetId)) {
            snap.nodeId = n->id;
            snap.description = n->description;
        }
    }
    return snap;
}

Document::DecisionSnapshot Document::decided(const Suggestion &suggestion,
                                             Suggestion::Status status) const
{
    DecisionSnapshot snap = snapshot(suggestion);
    const bool wasAccepted = snap.decision && snap.decision->status == Suggestion::Status::Accepted;
    snap.decision = SuggestionDecision::of(suggestion, status);
    if (!snap.nodeId.isEmpty()) {
        if (status == Suggestion::Status::Accepted)
            snap.description = suggestion.value;
        else if (wasAccepted && snap.description == suggestion.value)
            snap.description = m_analysisDescriptions.value(snap.nodeId); // take it back
    }
    return snap;
}

void Document::restore(const DecisionSnapshot &snapshot)
{
    m_corrected.reset();
    if (snapshot.decision)
        m_decisions.insert(snapshot.key, *snapshot.decision);
    else
        m_decisions.remove(snapshot.key);
    const Suggestion::Status status =
        snapshot.decision ? snapshot.decision->status : Suggestion::Status::Pending;
    QStringList changed;
    for (Suggestion &s : m_suggestionReport.suggestions)
        if (s.status != status && SuggestionDecision::keyOf(s) == snapshot.key) {
            s.status = status;
            changed << s.id;
        }
    const QStringList nodes = refreshDescriptions();
    for (const QString &id : std::as_const(changed))
        emitChange(DocumentChange::Suggestion, id);
    for (const QString &id : nodes)
        emitChange(DocumentChange::Node, id);
    markDecisionsChanged();
    emitChange(DocumentChange::Decisions);
}

void Document::loadDecisions()
{
    m_project = {};
    m_unsaved = false;
    m_modifiedOutside = false;
    m_migrationPending = false;
    const bool chosen = m_chosenProject && m_chosenProject->first == workspaceRoot();
    setProjectPath(chosen ? m_chosenProject->second : ProjectFile::locate(workspaceRoot()));
    QList<SuggestionDecision> keyed;
    const QString legacy =
        workspaceRoot().isEmpty() || chosen ? QString() : DecisionStore::path(workspaceRoot());
    if (!m_projectPath.isEmpty() && QFileInfo::exists(m_projectPath)) {
        QString error;
        if (ProjectFile::read(m_projectPath, &m_project, &error)) {
            keyed = m_project.decisions;
        } else {
            // kept under another name before anything is written over it
            const QString kept = ProjectFile::keepUnreadable(m_projectPath);
            Q_EMIT projectLoadFailed(kept.isEmpty()
                                         ? error
                                         : QCoreApplication::translate(
                                               "rosarch::Document", "%1\nThe file was kept as %2.")
                                               .arg(error, kept));
        }
    } else if (!legacy.isEmpty() && QFileInfo::exists(legacy)) {
        // Decisions of an earlier version, by position: taken over once, by the ids of the
        // model they are opened with (not an empty one), then written as the project and the
        // old file set aside.
        m_migrationPending = m_nodes.nodes.isEmpty();
        if (!m_migrationPending) {
            const StableKeys keys(Recovery{m_nodes, m_launch, m_architecture});
            for (const SuggestionDecision &d : DecisionStore::load(legacy)) {
                SuggestionDecision k;
                if (CorrectedModel::keyed(d, keys, &k))
                    keyed.append(k);
            }
            QFile::rename(legacy, legacy + QStringLiteral(".migrated"));
            m_modifiedOutside = !keyed.isEmpty();
        }
    }
    m_launchOptions = m_project.launch;
    bindDecisions(keyed);
    if (m_modifiedOutside)
        saveDecisions(); // migrated: on disk as the old file was
}

void Document::applyStoredDescriptions()
{
    refreshDescriptions();
}

void Document::markDecisionsChanged()
{
    m_unsaved = true;
    // Started by the first unsaved change, not restarted by later ones: a burst of decisions,
    // undos and redos is written once, and a person who keeps deciding faster than the
    // interval still has every change in the side file within one interval (what a crash can
    // lose).
    if (!m_autosave.isActive())
        m_autosave.start();
    updateModified();
}

bool Document::isModified() const
{
    return m_modifiedOutside || !m_undoStack.isClean();
}

void Document::updateModified()
{
    const bool modified = isModified();
    if (modified == m_modifiedShown)
        return;
    m_modifiedShown = modified;
    Q_EMIT modifiedChanged(modified);
}

void Document::setProjectPath(const QString &path)
{
    if (path == m_projectPath)
        return;
    m_projectPath = path;
    Q_EMIT projectPathChanged(path);
}

QString Document::autosaveFile() const
{
    if (workspaceRoot().isEmpty())
        return {};
    // A new project never saved keeps its changes where the workspace's project would.
    return ProjectFile::autosavePath(m_projectPath.isEmpty() ? ProjectFile::locate(workspaceRoot())
                                                             : m_projectPath);
}

bool Document::writeAutosave()
{
    m_autosave.stop();
    if (!m_unsaved)
        return true;
    const QString side = autosaveFile();
    if (side.isEmpty() || !isModified()) { // no workspace, or back to what the file holds
        if (!side.isEmpty())
            QFile::remove(side);
        m_unsaved = false;
        return true;
    }
    Project p = project();
    p.workspace = ProjectFile::workspaceField(side, workspaceRoot());
    QString error;
    if (!ProjectFile::write(side, p, &error)) {
        // kept in memory; the next change, save or close tries again
        Q_EMIT decisionsSaveFailed(
            QCoreApplication::translate("rosarch::Document", "autosave: %1").arg(error));
        return false;
    }
    m_unsaved = false;
    return true;
}

bool Document::saveDecisions()
{
    if (workspaceRoot().isEmpty()) { // no workspace: nothing to keep them with
        m_autosave.stop();
        m_unsaved = false;
        return true;
    }
    if (m_projectPath.isEmpty())
        return false; // a new project: saveProjectAs
    return saveProjectAs(m_projectPath);
}

bool Document::saveProjectAs(const QString &file)
{
    m_autosave.stop();
    Project p = project();
    p.workspace = ProjectFile::workspaceField(file, workspaceRoot());
    QString error;
    if (!ProjectFile::write(file, p, &error)) {
        Q_EMIT decisionsSaveFailed(error); // kept in memory and modified
        if (m_unsaved)
            m_autosave.start();
        return false;
    }
    if (const QString side = autosaveFile(); !side.isEmpty())
        QFile::remove(side);
    if (file != ProjectFile::locate(workspaceRoot()))
        m_chosenProject = std::make_pair(workspaceRoot(), file);
    setProjectPath(file);
    QFile::remove(autosaveFile());
    m_unsaved = false;
    m_modifiedOutside = false;
    m_undoStack.setClean();
    updateModified();
    return true;
}

void Document::discardChanges()
{
    m_autosave.stop();
    discardAutosave();
    m_unsaved = false;
    m_modifiedOutside = false;
    m_undoStack.setClean();
    updateModified();
}

void Document::discardAutosave()
{
    if (const QString side = autosaveFile(); !side.isEmpty())
        QFile::remove(side);
}

bool Document::recoverAutosave(QString *error)
{
    const QString side = autosaveFile();
    Project recovered;
    if (side.isEmpty() || !ProjectFile::read(side, &recovered, error))
        return false;
    reloadWith([this, &recovered] {
        m_project = recovered;
        m_project.workspace.clear();
        m_launchOptions = recovered.launch;
        bindDecisions(recovered.decisions);
        m_modifiedOutside = true; // the side file holds it, the project file does not
        m_unsaved = false;
    });
    return true;
}

void Document::setProjectFile(const QString &workspaceRoot, const QString &file)
{
    m_chosenProject = std::make_pair(workspaceRoot, file);
    if (!workspaceRoot.isEmpty() && workspaceRoot == this->workspaceRoot())
        reloadWith([this] { loadDecisions(); });
}

void Document::reloadWith(const std::function<void()> &load)
{
    const LaunchOptions before = m_launchOptions;
    DocumentChange change{DocumentChange::Model | DocumentChange::Decisions, {}};
    Q_EMIT aboutToChange(change);
    m_autosave.stop();
    m_corrected.reset();
    for (AtomicNode &n : m_nodes.nodes)
        n.description = m_analysisDescriptions.value(n.id, n.description);
    m_modifiedOutside = false;
    m_undoStack.clear();
    load();
    if (m_launchOptions != before)
        change.parts |= DocumentChange::LaunchOptions;
    updateModified();
    Q_EMIT changed(change);
    if (hasSuggestionReport()) {
        SuggestionReport report = m_suggestionReport; // statuses from this project's decisions
        setSuggestions(std::move(report));
    }
}

} // namespace rosarch
