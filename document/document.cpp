#include "document/document.h"
#include "jobs/disposal.h"
#include "jobs/stallprobe.h"

#include <QEventLoop>
#include <QTimer>

#include <utility>

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent), m_session(new ProjectSession(this))
{
    connect(&m_acceptedJobs, &JobRunner::failed, this, [this](const QString &message) {
        // the model as recovered stands for it; a person sees the project was not applied
        qWarning("rosarch: the project could not be applied to the model: %s", qPrintable(message));
        m_acceptedStarted = m_acceptedChange;
        m_acceptedPending = false;
        emitChange(DocumentChange::Accepted);
    });
}

Document::~Document()
{
    delete m_session; // writes the autosave side file, reading this document's model
}

void Document::emitChange(DocumentChange::Parts parts, const QString &id)
{
    Q_EMIT changed(DocumentChange{parts, id});
}

void Document::setRecovery(Recovery recovery)
{
    const StallScope scope("Document::setRecovery");
    ProjectSession::Carried carried = m_session->beginReplace(true, recovery.nodes.workspaceRoot);
    DocumentChange change{DocumentChange::Model | DocumentChange::Decisions, {}};
    if (carried.hadSuggestions)
        change.parts |= DocumentChange::Suggestions;
    {
        const StallScope views("Document::aboutToChange (views)");
        Q_EMIT aboutToChange(change);
    }
    m_session->dropKeys();
    m_undoStack.clear();
    disposeInBackground(Recovery{std::exchange(m_nodes, std::move(recovery.nodes)),
                                 std::exchange(m_launch, std::move(recovery.launch)),
                                 std::exchange(m_architecture, std::move(recovery.architecture))});
    m_analysisDescriptions.clear();
    for (const AtomicNode &n : m_nodes.nodes)
        m_analysisDescriptions.insert(n.id, n.description);
    change.parts |= m_session->endReplace(true, carried);
    resetAccepted();
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
    ProjectSession::Carried carried = m_session->beginReplace(false, workspaceRoot());
    DocumentChange change{DocumentChange::Launch | DocumentChange::Decisions, {}};
    if (carried.hadSuggestions)
        change.parts |= DocumentChange::Suggestions;
    Q_EMIT aboutToChange(change);
    m_session->dropKeys();
    disposeInBackground(std::make_pair(std::exchange(m_launch, std::move(launch)),
                                       std::exchange(m_architecture, std::move(architecture))));
    change.parts |= m_session->endReplace(false, carried);
    resetAccepted();
    Q_EMIT changed(change);
}

QStringList Document::setDescriptions(const QHash<QString, QString> &wanted)
{
    QStringList changed;
    for (AtomicNode &n : m_nodes.nodes)
        if (const auto it = wanted.constFind(n.id); it != wanted.cend() && n.description != *it) {
            n.description = *it;
            changed << n.id;
        }
    if (!changed.isEmpty())
        dropAccepted();
    return changed;
}

void Document::dropAccepted()
{
    ++m_acceptedChange;
    m_acceptedPending = true;
    if (m_acceptedScheduled)
        return;
    m_acceptedScheduled = true;
    QTimer::singleShot(0, this, [this] {
        m_acceptedScheduled = false;
        if (m_acceptedStarted != m_acceptedChange)
            startAccepted();
    });
}

void Document::settleAccepted()
{
    if (!m_acceptedPending)
        return;
    QEventLoop loop;
    connect(this, &Document::changed, &loop, [this, &loop](const DocumentChange &change) {
        if (change.has(DocumentChange::Accepted) && !m_acceptedPending)
            loop.quit();
    });
    loop.exec(QEventLoop::ExcludeUserInputEvents);
}

void Document::startAccepted()
{
    // The model as analysis found it: the nodes here hold the descriptions accepted or edited
    // since, which the project applies itself (the same function as every export and the
    // command line). Both are copies that share their data until written to.
    const Project project = m_session->project();
    m_acceptedStarted = m_acceptedChange;
    m_acceptedJobs.start<CorrectedRecovery>(
        [recovered = recovered(), project](const JobControl &) {
            if (project.decisions.isEmpty() && project.corrections.isEmpty()) {
                CorrectedRecovery same; // nothing to apply (and no keys to make)
                same.recovery = recovered;
                return same;
            }
            return CorrectedModel::apply(recovered, project);
        },
        [this, change = m_acceptedChange](CorrectedRecovery result, bool canceled) {
            if (canceled)
                return;
            disposeInBackground(std::exchange(m_corrected, std::move(result)));
            m_acceptedPending = change != m_acceptedChange; // else a newer job is coming
            emitChange(DocumentChange::Accepted);
        });
}

void Document::resetAccepted()
{
    const Project project = m_session->project();
    CorrectedRecovery now;
    now.recovery = recovered();
    disposeInBackground(std::exchange(m_corrected, std::move(now)));
    if (project.decisions.isEmpty() && project.corrections.isEmpty()) {
        // nothing to apply: the model as recovered (without keying a large model)
        m_acceptedJobs.cancel(); // a job of the model before
        m_acceptedStarted = m_acceptedChange;
        m_acceptedPending = false;
        return;
    }
    m_acceptedPending = true;
    startAccepted();
}

} // namespace rosarch
