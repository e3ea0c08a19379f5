#include "document/document.h"
#include "jobs/disposal.h"
#include "jobs/stallprobe.h"

#include <utility>

namespace rosarch {

Document::Document(QObject *parent) : QObject(parent), m_session(new ProjectSession(this)) {}

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
    disposeInBackground(std::exchange(m_corrected, std::nullopt));
    m_session->dropKeys();
    m_undoStack.clear();
    disposeInBackground(Recovery{std::exchange(m_nodes, std::move(recovery.nodes)),
                                 std::exchange(m_launch, std::move(recovery.launch)),
                                 std::exchange(m_architecture, std::move(recovery.architecture))});
    m_analysisDescriptions.clear();
    for (const AtomicNode &n : m_nodes.nodes)
        m_analysisDescriptions.insert(n.id, n.description);
    change.parts |= m_session->endReplace(true, carried);
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
    m_corrected.reset();
    m_session->dropKeys();
    disposeInBackground(std::make_pair(std::exchange(m_launch, std::move(launch)),
                                       std::exchange(m_architecture, std::move(architecture))));
    change.parts |= m_session->endReplace(false, carried);
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
        m_corrected.reset();
    return changed;
}

const Recovery &Document::accepted() const
{
    return corrected().recovery;
}

const CorrectedRecovery &Document::corrected() const
{
    if (!m_corrected) {
        // The model as analysis found it: the nodes here hold the descriptions accepted or
        // edited since, which the project applies itself (the same function as every export
        // and the command line).
        Recovery recovered = this->recovered();
        const Project p = m_session->project();
        if (p.decisions.isEmpty() && p.corrections.isEmpty()) {
            // nothing to apply: the model as recovered (without keying a large model)
            m_corrected = CorrectedRecovery{};
            m_corrected->recovery = std::move(recovered);
        } else {
            m_corrected = CorrectedModel::apply(recovered, p);
        }
    }
    return *m_corrected;
}

} // namespace rosarch
