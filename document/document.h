#pragma once

#include "core/atomicnodelist.h"
#include "core/launchdependencies.h"
#include "document/documentchange.h"
#include "document/projectsession.h"
#include "jobs/jobrunner.h"
#include "pipeline/recovery.h"
#include "project/correctedmodel.h"

#include <QHash>
#include <QObject>
#include <QUndoStack>

#include <optional>

namespace rosarch {

class ProjectSession;

/// The open recovery: the model the stages recovered for a workspace, the model as accepted
/// (with the project's decisions and corrections applied), and the undo stack for every change
/// a person makes. Views read from here; edits go through commands on the undo stack, made by
/// the ProjectSession, which keeps the project (decisions, corrections, finding marks, its file).
/// Every change is announced by one signal, `changed`, saying what changed.
class Document : public QObject
{
    Q_OBJECT
public:
    explicit Document(QObject *parent = nullptr);
    ~Document() override;

    QString workspaceRoot() const { return m_nodes.workspaceRoot; }
    const AtomicNodeList &atomicNodes() const { return m_nodes; }
    /// Stage 2's result; empty until stage 2 ran.
    const LaunchDependencies &launchDependencies() const { return m_launch; }
    /// Stage 3's result (composites per launch-file instance); empty until stage 3 ran.
    const Architecture &architecture() const { return m_architecture; }
    QUndoStack *undoStack() { return &m_undoStack; }
    /// The project of this recovery: suggestions, decisions, corrections, finding marks, launch
    /// options and the project file.
    ProjectSession *session() const { return m_session; }

    /// Replaces the whole model with the result of stages 1 and 2 (clears undo history); the
    /// project is bound to it again, or read when the workspace is another.
    void setRecovery(Recovery recovery);
    /// The model as the stages recovered it (descriptions as analysis found them): what a
    /// re-run that found nothing new returns.
    Recovery recovered() const;
    /// Replaces the whole model with a stage 1 result and no launch dependencies.
    void setAtomicNodes(AtomicNodeList nodes);
    /// Replaces only the results of stages 2 and 3 (a re-run of stage 2); the atomic nodes
    /// and their undo history stay.
    void setLaunchDependencies(LaunchDependencies launch, Architecture architecture = {});

    /// The model as accepted (CorrectedModel::apply of the recovery and the project): what the
    /// diagram draws and the exports write. A change of either makes it again on a background
    /// job (applying a correction may compose stage 3 again); until that job is done this is
    /// the one before, or after a new model the model as recovered, and isAcceptedPending() is
    /// true. `changed` with DocumentChange::Accepted says it is there.
    const Recovery &accepted() const { return m_corrected.recovery; }
    /// True while the model as accepted is being made again (accepted() is not current).
    bool isAcceptedPending() const { return m_acceptedPending; }
    /// Runs the event loop (without user input) until the model as accepted includes every
    /// change made so far: for what must write exactly what a person reviewed (exports).
    void settleAccepted();

Q_SIGNALS:
    /// Lists the views show from scratch are about to be replaced (change.isReset()): item
    /// models begin their reset here.
    void aboutToChange(const rosarch::DocumentChange &change);
    /// Something changed; `change` says what.
    void changed(const rosarch::DocumentChange &change);

private:
    friend class ProjectSession; // announces its changes, sets descriptions
    void emitChange(DocumentChange::Parts parts, const QString &id = {});
    /// The model as accepted, with what of the project matched nothing.
    const CorrectedRecovery &corrected() const { return m_corrected; }
    /// The project or the descriptions changed: the model as accepted is made again, once for
    /// every change made before the event loop runs.
    void dropAccepted();
    /// Starts the job that makes the model as accepted of the model and project as they are.
    void startAccepted();
    /// After a new model: the model as recovered stands for the model as accepted until the job
    /// makes it (at once when the project changes nothing).
    void resetAccepted();
    /// The nodes' descriptions as stage 1 found them, by node id.
    const QHash<QString, QString> &analysisDescriptions() const { return m_analysisDescriptions; }
    /// Gives each node in `wanted` its description there; returns the ids that changed.
    QStringList setDescriptions(const QHash<QString, QString> &wanted);

    AtomicNodeList m_nodes;
    LaunchDependencies m_launch;
    Architecture m_architecture;
    CorrectedRecovery m_corrected;                  ///< accepted(): the last one made
    QHash<QString, QString> m_analysisDescriptions; ///< as stage 1 found them, by node id
    QUndoStack m_undoStack;
    ProjectSession *m_session;
    JobRunner m_acceptedJobs;         ///< makes m_corrected; a newer job drops an older result
    bool m_acceptedPending = false;   ///< a change is not in m_corrected yet
    bool m_acceptedScheduled = false; ///< startAccepted is queued
    quint64 m_acceptedChange = 0;     ///< counts the changes of what the model as accepted is of
    quint64 m_acceptedStarted = 0;    ///< the change the last job started with
};

} // namespace rosarch
