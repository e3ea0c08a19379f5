// Document: the project on disk: loading, migration, saving, the modified state, autosave.
#include "accepted/decisionstore.h"
#include "document/correctioncommand.h"
#include "document/decidesuggestioncommand.h"
#include "document/document.h"
#include "project/project.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSet>

namespace rosarch {

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
