#include "document.h"
#include "decidesuggestioncommand.h"
#include "decisionstore.h"
#include "setnodedescriptioncommand.h"

#include <QCoreApplication>
#include <QSet>

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent) {}

void Document::setRecovery(Recovery recovery)
{
    Q_EMIT modelAboutToBeReset();
    m_accepted.reset();
    m_undoStack.clear();
    m_nodes = std::move(recovery.nodes);
    m_launch = std::move(recovery.launch);
    m_architecture = std::move(recovery.architecture);
    m_analysisDescriptions.clear();
    for (const AtomicNode &n : m_nodes.nodes)
        m_analysisDescriptions.insert(n.id, n.description);
    loadDecisions();
    Q_EMIT modelReset();
    // The old suggestions were checked against the old model; their ids may mean other things.
    clearSuggestions();
    Q_EMIT decisionsChanged();
}

void Document::setAtomicNodes(AtomicNodeList nodes)
{
    setRecovery({std::move(nodes), {}, {}});
}

void Document::setLaunchDependencies(LaunchDependencies launch, Architecture architecture)
{
    Q_EMIT launchDependenciesAboutToBeReset();
    m_accepted.reset();
    m_launch = std::move(launch);
    m_architecture = std::move(architecture);
    Q_EMIT launchDependenciesReset();
    clearSuggestions(); // groupings and names refer to launch ids that may have changed
    Q_EMIT decisionsChanged();
}

void Document::setLaunchOptions(const LaunchOptions &options)
{
    if (options == m_launchOptions)
        return;
    m_launchOptions = options;
    Q_EMIT launchOptionsChanged(m_launchOptions);
}

void Document::setNodeDescription(const QString &nodeId, const QString &description)
{
    const AtomicNode *node = m_nodes.node(nodeId);
    if (!node || node->description == description)
        return;
    m_undoStack.push(new SetNodeDescriptionCommand(this, nodeId, node->description, description));
}

void Document::applyNodeDescription(const QString &nodeId, const QString &description)
{
    for (AtomicNode &n : m_nodes.nodes) {
        if (n.id == nodeId) {
            n.description = description;
            m_accepted.reset();
            Q_EMIT nodeChanged(nodeId);
            return;
        }
    }
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
    Q_EMIT suggestionsAboutToBeReset();
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
        m_accepted.reset();
    Q_EMIT suggestionsReset();
    for (const QString &id : std::as_const(changedNodes))
        Q_EMIT nodeChanged(id);
    return decidedBefore;
}

void Document::clearSuggestions()
{
    const SuggestionReport &r = m_suggestionReport;
    if (r.suggestions.isEmpty() && r.prompts.isEmpty() && r.errors.isEmpty() &&
        r.discarded.isEmpty())
        return;
    Q_EMIT suggestionsAboutToBeReset();
    m_suggestionReport = {};
    Q_EMIT suggestionsReset();
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
    if (!m_accepted) {
        const Recovery recovery{m_nodes, m_launch, m_architecture};
        AcceptedDecisions decisions = AcceptedModel::select(m_decisions, recovery);
        // The nodes here already hold every description a person set, by accepting or by
        // editing after accepting; the stored decision must not undo a later edit.
        decisions.descriptions.clear();
        m_accepted = AcceptedModel::apply(recovery, decisions);
    }
    return *m_accepted;
}

QString Document::decisionsPath() const
{
    return DecisionStore::path(workspaceRoot());
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
    m_accepted.reset();
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
    if (!snapshot.nodeId.isEmpty()) {
        const AtomicNode *n = m_nodes.node(snapshot.nodeId);
        if (n && n->description != snapshot.description)
            applyNodeDescription(snapshot.nodeId, snapshot.description);
    }
    for (const QString &id : std::as_const(changed))
        Q_EMIT suggestionChanged(id);
    saveDecisions();
    Q_EMIT decisionsChanged();
}

void Document::loadDecisions()
{
    m_decisions = DecisionStore::load(decisionsPath());
    for (const SuggestionDecision &d : std::as_const(m_decisions)) {
        if (d.kind != Suggestion::Kind::NodeDescription || d.status != Suggestion::Status::Accepted)
            continue;
        for (AtomicNode &n : m_nodes.nodes)
            if (n.id == d.targetId)
                n.description = d.proposal;
    }
}

void Document::saveDecisions()
{
    QString error;
    if (!DecisionStore::save(decisionsPath(), workspaceRoot(), m_decisions, &error))
        Q_EMIT decisionsSaveFailed(error);
}

} // namespace rosarch
