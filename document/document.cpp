#include "document/document.h"
#include "accepted/decisionstore.h"
#include "document/correctioncommand.h"
#include "document/decidesuggestioncommand.h"
#include "jobs/disposal.h"
#include "jobs/stallprobe.h"
#include "project/project.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSet>

#include <utility>

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent)
{
    m_autosave.setSingleShot(true);
    m_autosave.setInterval(2000);
    connect(&m_autosave, &QTimer::timeout, this, [this] { writeAutosave(); });
    connect(&m_undoStack, &QUndoStack::cleanChanged, this, [this] { updateModified(); });
    connect(&m_keysWatcher, &QFutureWatcherBase::finished, this, [this] {
        if (keysReady()) // else a job of a model since replaced
            Q_EMIT keysMade();
    });
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
    const StallScope scope("Document::setRecovery");
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
    {
        const StallScope views("Document::aboutToChange (views)");
        Q_EMIT aboutToChange(change);
    }
    disposeInBackground(std::make_pair(std::exchange(m_corrected, std::nullopt),
                                       std::exchange(m_keys, std::nullopt)));
    m_keysJob = {};                                // of the old model: left to finish, dropped
    m_modifiedOutside = sameWorkspace && modified; // undo history goes, the changes stay
    m_undoStack.clear();
    disposeInBackground(Recovery{std::exchange(m_nodes, std::move(recovery.nodes)),
                                 std::exchange(m_launch, std::move(recovery.launch)),
                                 std::exchange(m_architecture, std::move(recovery.architecture))});
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
    startKeys();
    const StallScope views("Document::changed (views)");
    Q_EMIT changed(change);
}

Recovery Document::recovered() const
{
    Recovery r{m_nodes, m_launch, m_architecture};
    for (AtomicNode &n : r.nodes.nodes)
        if (const auto it = m_analysisDescriptions.constFind(n.id);
            it != m_analysisDescriptions.cend() && *it != n.description)
            n.description = *it;
    return r;
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
    m_keysJob = {}; // of the old model: left to finish, dropped
    disposeInBackground(std::make_pair(std::exchange(m_launch, std::move(launch)),
                                       std::exchange(m_architecture, std::move(architecture))));
    bindDecisions(keyed);
    bindSuggestions(suggestions); // by key: groupings and names refer to launch ids
    startKeys();
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

} // namespace rosarch
