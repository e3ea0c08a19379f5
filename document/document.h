#pragma once

#include "core/atomicnodelist.h"
#include "core/launchdependencies.h"
#include "document/documentchange.h"
#include "document/projectsession.h"
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
    /// diagram draws and the exports write. Computed once per change of either.
    const Recovery &accepted() const;

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
    const CorrectedRecovery &corrected() const;
    /// Forgets the model as accepted (the project or the descriptions changed).
    void dropAccepted() { m_corrected.reset(); }
    /// The nodes' descriptions as stage 1 found them, by node id.
    const QHash<QString, QString> &analysisDescriptions() const { return m_analysisDescriptions; }
    /// Gives each node in `wanted` its description there; returns the ids that changed.
    QStringList setDescriptions(const QHash<QString, QString> &wanted);

    AtomicNodeList m_nodes;
    LaunchDependencies m_launch;
    Architecture m_architecture;
    mutable std::optional<CorrectedRecovery> m_corrected; ///< accepted(), until a change
    QHash<QString, QString> m_analysisDescriptions;       ///< as stage 1 found them, by node id
    QUndoStack m_undoStack;
    ProjectSession *m_session;
};

} // namespace rosarch
