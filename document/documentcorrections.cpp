// Document: the model as corrected, stable keys, and corrections (blueprint §5).
#include "accepted/decisionstore.h"
#include "core/threadpriority.h"
#include "document/correctioncommand.h"
#include "document/decidesuggestioncommand.h"
#include "document/document.h"
#include "project/project.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSet>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>

#include <pwd.h>
#include <unistd.h>

namespace rosarch {

const Recovery &Document::accepted() const
{
    if (!m_corrected) {
        // The model as analysis found it: the nodes here hold the descriptions accepted or
        // edited since, which the project applies itself (the same function as every export
        // and the command line).
        Recovery recovered{m_nodes, m_launch, m_architecture};
        for (AtomicNode &n : recovered.nodes.nodes)
            n.description = m_analysisDescriptions.value(n.id, n.description);
        const Project p = project();
        if (p.decisions.isEmpty() && p.corrections.isEmpty()) {
            // nothing to apply: the model as recovered (without keying a large model)
            m_corrected = CorrectedRecovery{};
            m_corrected->recovery = std::move(recovered);
        } else {
            m_corrected = CorrectedModel::apply(recovered, p);
        }
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

void Document::bindDecisions(const QList<SuggestionDecision> &keyed)
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
    return recoveredKeys().keyOf(id);
}

const StableKeys &Document::recoveredKeys() const
{
    if (!m_keys) {
        // Waiting for the job costs less than starting over; one not started yet runs here.
        m_keys = m_keysJob.isValid() ? m_keysJob.result()
                                     : StableKeys(Recovery{m_nodes, m_launch, m_architecture});
        m_keysJob = {};
    }
    return *m_keys;
}

bool Document::keysReady() const
{
    return m_keys || (m_keysJob.isValid() && m_keysJob.isFinished());
}

void Document::startKeys()
{
    if (m_keys)
        return;
    // A small model's keys take a few ms: made here, they are there when a view asks.
    constexpr qsizetype kSmallModel = 1000;
    if (m_nodes.nodes.size() + m_launch.instances.size() + m_launch.nodes.size() +
            m_launch.classifierNodes.size() + m_architecture.composites.size() <
        kSmallModel) {
        recoveredKeys();
        return;
    }
    static QThreadPool pool; // not the global pool, which painting waits for
    pool.setMaxThreadCount(1);
    m_keysJob = QtConcurrent::run(&pool, [recovery = Recovery{m_nodes, m_launch, m_architecture}] {
        lowerThisThreadPriority(BackgroundPriority::YieldToUi); // its pool's own thread
        return StableKeys(recovery);
    });
    m_keysWatcher.setFuture(m_keysJob);
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

QString Document::author()
{
    const QString configured = qEnvironmentVariable("ROSARCH_AUTHOR");
    if (!configured.isEmpty())
        return configured;
    const QString user = qEnvironmentVariable("USER", qEnvironmentVariable("USERNAME"));
    if (!user.isEmpty())
        return user;
    // A session without USER (a desktop launcher, a service): the account's own name.
    if (const passwd *account = ::getpwuid(::getuid()); account && account->pw_name)
        return QString::fromLocal8Bit(account->pw_name);
    return QStringLiteral("unknown");
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

} // namespace rosarch
