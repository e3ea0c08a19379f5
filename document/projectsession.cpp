// ProjectSession: suggestions, decisions, corrections and finding marks, bound to the model by
// stable key; the keys themselves.
#include "document/projectsession.h"
#include "accepted/acceptedmodel.h"
#include "core/threadpriority.h"
#include "document/correctioncommand.h"
#include "document/decidesuggestioncommand.h"
#include "document/document.h"
#include "document/findingmarkcommand.h"
#include "jobs/disposal.h"

#include <QCoreApplication>
#include <QSet>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include <pwd.h>
#include <unistd.h>

namespace rosarch {

ProjectSession::ProjectSession(Document *document) : QObject(document), m_document(document)
{
    m_autosave.setSingleShot(true);
    m_autosave.setInterval(2000);
    connect(&m_autosave, &QTimer::timeout, this, [this] { writeAutosave(); });
    connect(document->undoStack(), &QUndoStack::cleanChanged, this, [this] { updateModified(); });
    connect(&m_keysWatcher, &QFutureWatcherBase::finished, this, [this] {
        if (keysReady()) // else a job of a model since replaced
            Q_EMIT keysMade();
    });
}

ProjectSession::~ProjectSession()
{
    writeAutosave(); // not a save: the next open offers to recover it
}

void ProjectSession::announce(DocumentChange::Parts parts, const QString &id)
{
    m_document->emitChange(parts, id);
}

ProjectSession::Carried ProjectSession::beginReplace(bool all, const QString &workspaceRoot)
{
    // A re-run of the same workspace keeps the project in memory, modified or not; another
    // workspace's project replaces it, its changes kept in the autosave side file first.
    Carried carried;
    carried.sameWorkspace = !all || workspaceRoot == m_document->workspaceRoot();
    carried.decisions = keyedDecisions(); // by the keys of the old model
    // The suggestions were made on the old model: they stay, by key, where their subject is
    // still there (its id may be another now), and go where it is gone.
    if (carried.sameWorkspace)
        carried.suggestions = keyedSuggestions();
    carried.launchOptions = m_launchOptions;
    carried.hadSuggestions = hasSuggestionReport();
    if (all) {
        const bool modified = isModified();
        if (!carried.sameWorkspace)
            writeAutosave();
        m_modifiedOutside = carried.sameWorkspace && modified; // undo history goes, changes stay
    }
    return carried;
}

DocumentChange::Parts ProjectSession::endReplace(bool all, const Carried &carried)
{
    DocumentChange::Parts parts;
    if (!all || (carried.sameWorkspace && !m_migrationPending)) {
        bindDecisions(carried.decisions); // re-bound from memory, by key
    } else {
        if (m_chosenProject && m_chosenProject->first != m_document->workspaceRoot())
            m_chosenProject.reset(); // that project belongs to another workspace
        load();
    }
    if (m_launchOptions != carried.launchOptions)
        parts |= DocumentChange::LaunchOptions;
    if (carried.sameWorkspace)
        bindSuggestions(carried.suggestions);
    else
        m_suggestionReport = {};
    if (all)
        updateModified();
    startKeys();
    return parts;
}

void ProjectSession::setLaunchOptions(const LaunchOptions &options)
{
    if (options == m_launchOptions)
        return;
    m_launchOptions = options;
    m_modifiedOutside = true; // not an undo step
    markChanged();
    announce(DocumentChange::LaunchOptions);
}

void ProjectSession::adoptLaunchOptions(const LaunchOptions &options)
{
    if (options == m_launchOptions)
        return;
    m_launchOptions = options;
    announce(DocumentChange::LaunchOptions);
}

// Suggestions and decisions.

const Suggestion *ProjectSession::suggestion(const QString &id) const
{
    for (const Suggestion &s : m_suggestionReport.suggestions)
        if (s.id == id)
            return &s;
    return nullptr;
}

int ProjectSession::setSuggestions(SuggestionReport report)
{
    Q_EMIT m_document->aboutToChange({DocumentChange::Suggestions, {}});
    int decidedBefore = 0;
    QHash<QString, QString> described;
    for (Suggestion &s : report.suggestions) {
        const auto it = m_decisions.constFind(SuggestionDecision::keyOf(s));
        s.status = it == m_decisions.cend() ? Suggestion::Status::Pending : it->status;
        if (it == m_decisions.cend())
            continue;
        ++decidedBefore;
        if (s.status == Suggestion::Status::Accepted && s.kind == Suggestion::Kind::NodeDescription)
            described.insert(s.targetId, s.value);
    }
    m_suggestionReport = std::move(report);
    const QStringList changedNodes = m_document->setDescriptions(described);
    announce(DocumentChange::Suggestions);
    for (const QString &id : changedNodes)
        announce(DocumentChange::Node, id);
    return decidedBefore;
}

bool ProjectSession::hasSuggestionReport() const
{
    const SuggestionReport &r = m_suggestionReport;
    return !r.suggestions.isEmpty() || !r.prompts.isEmpty() || !r.errors.isEmpty() ||
           !r.discarded.isEmpty();
}

bool ProjectSession::acceptSuggestion(const QString &id)
{
    const Suggestion *s = suggestion(id);
    if (!s || s->status == Suggestion::Status::Accepted)
        return false;
    m_document->undoStack()->push(
        new DecideSuggestionCommand(this, *s, Suggestion::Status::Accepted));
    return true;
}

bool ProjectSession::rejectSuggestion(const QString &id)
{
    const Suggestion *s = suggestion(id);
    if (!s || s->status == Suggestion::Status::Rejected)
        return false;
    m_document->undoStack()->push(
        new DecideSuggestionCommand(this, *s, Suggestion::Status::Rejected));
    return true;
}

int ProjectSession::acceptAllSuggestions(Suggestion::Kind kind)
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
    m_document->undoStack()->push(macro);
    return int(pending.size());
}

QList<SubsystemGroup> ProjectSession::acceptedGroupings() const
{
    return AcceptedModel::select(m_decisions,
                                 {m_document->atomicNodes(), m_document->launchDependencies(),
                                  m_document->architecture()})
        .groupings;
}

QMap<QString, QString> ProjectSession::acceptedNames() const
{
    return AcceptedModel::select(m_decisions,
                                 {m_document->atomicNodes(), m_document->launchDependencies(),
                                  m_document->architecture()})
        .names;
}

ProjectSession::DecisionSnapshot ProjectSession::snapshot(const Suggestion &suggestion) const
{
    DecisionSnapshot snap;
    snap.key = SuggestionDecision::keyOf(suggestion);
    if (const auto it = m_decisions.constFind(snap.key); it != m_decisions.cend())
        snap.decision = *it;
    return snap;
}

ProjectSession::DecisionSnapshot ProjectSession::decided(const Suggestion &suggestion,
                                                         Suggestion::Status status) const
{
    DecisionSnapshot snap = snapshot(suggestion);
    snap.decision = SuggestionDecision::of(suggestion, status);
    return snap;
}

void ProjectSession::restore(const DecisionSnapshot &snapshot)
{
    m_document->dropAccepted();
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
        announce(DocumentChange::Suggestion, id);
    for (const QString &id : nodes)
        announce(DocumentChange::Node, id);
    markChanged();
    announce(DocumentChange::Decisions);
}

QStringList ProjectSession::refreshDescriptions()
{
    // as analysis found them, then accepted suggestions, then a person's own edits in order
    QHash<QString, QString> wanted = m_document->analysisDescriptions();
    for (const SuggestionDecision &d : std::as_const(m_decisions))
        if (d.kind == Suggestion::Kind::NodeDescription &&
            d.status == Suggestion::Status::Accepted && wanted.contains(d.targetId))
            wanted.insert(d.targetId, d.proposal);
    bool anyEdit = false;
    for (const Correction &c : std::as_const(m_project.corrections))
        anyEdit = anyEdit || c.kind == Correction::Kind::Describe;
    if (anyEdit) {
        QHash<QString, QString> idOfKey;
        for (const AtomicNode &n : m_document->atomicNodes().nodes)
            idOfKey.insert(keyOf(n.id), n.id);
        for (const Correction &c : std::as_const(m_project.corrections))
            if (c.kind == Correction::Kind::Describe && idOfKey.contains(c.target))
                wanted.insert(idOfKey.value(c.target), c.newValue);
    }
    return m_document->setDescriptions(wanted);
}

QList<SuggestionDecision> ProjectSession::keyedDecisions() const
{
    QList<SuggestionDecision> out = m_unboundDecisions;
    if (m_decisions.isEmpty())
        return out;
    const StableKeys &keys = recoveredKeys();
    for (const SuggestionDecision &d : m_decisions) {
        SuggestionDecision k;
        if (CorrectedModel::keyed(d, keys, &k))
            out.append(k);
    }
    return out;
}

void ProjectSession::bindDecisions(const QList<SuggestionDecision> &keyed)
{
    m_decisions.clear();
    m_unboundDecisions.clear();
    for (const SuggestionDecision &d : keyed) {
        SuggestionDecision b;
        QString reason;
        if (CorrectedModel::bound(d, recoveredKeys(), &b, &reason))
            m_decisions.insert(b.key(), b);
        else
            m_unboundDecisions.append(d); // kept, applied to nothing
    }
    m_document->dropAccepted();
    refreshDescriptions();
}

QList<Suggestion> ProjectSession::keyedSuggestions() const
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

void ProjectSession::bindSuggestions(const QList<Suggestion> &keyed)
{
    if (keyed.isEmpty()) {
        m_suggestionReport.suggestions.clear();
        return;
    }
    const StableKeys &keys = recoveredKeys();
    QList<Suggestion> bound;
    for (Suggestion s : keyed) {
        s.targetId = keys.idOf(s.targetId);
        bool there = !s.targetId.isEmpty();
        for (QString &m : s.memberIds) {
            m = keys.idOf(m);
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

// Stable keys.

QString ProjectSession::keyOf(const QString &id) const
{
    return recoveredKeys().keyOf(id);
}

const StableKeys &ProjectSession::recoveredKeys() const
{
    if (!m_keys) {
        // Waiting for the job costs less than starting over; one not started yet runs here.
        m_keys =
            m_keysJob.isValid()
                ? m_keysJob.result()
                : StableKeys(Recovery{m_document->atomicNodes(), m_document->launchDependencies(),
                                      m_document->architecture()});
        m_keysJob = {};
    }
    return *m_keys;
}

bool ProjectSession::keysReady() const
{
    return m_keys || (m_keysJob.isValid() && m_keysJob.isFinished());
}

void ProjectSession::dropKeys()
{
    disposeInBackground(std::exchange(m_keys, std::nullopt));
    m_keysJob = {}; // of the old model: left to finish, dropped
}

void ProjectSession::startKeys()
{
    if (m_keys)
        return;
    // A small model's keys take a few ms: made here, they are there when a view asks.
    constexpr qsizetype kSmallModel = 1000;
    const Document &d = *m_document;
    if (d.atomicNodes().nodes.size() + d.launchDependencies().instances.size() +
            d.launchDependencies().nodes.size() + d.launchDependencies().classifierNodes.size() +
            d.architecture().composites.size() <
        kSmallModel) {
        recoveredKeys();
        return;
    }
    static QThreadPool pool; // not the global pool, which painting waits for
    pool.setMaxThreadCount(1);
    m_keysJob = QtConcurrent::run(
        &pool, [recovery = Recovery{d.atomicNodes(), d.launchDependencies(), d.architecture()}] {
            lowerThisThreadPriority(BackgroundPriority::YieldToUi); // its pool's own thread
            return StableKeys(recovery);
        });
    m_keysWatcher.setFuture(m_keysJob);
}

} // namespace rosarch
