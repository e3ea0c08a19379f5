// ProjectSession: the project on disk: loading, migration, saving, the modified state, autosave.
#include "accepted/decisionstore.h"
#include "document/correctioncommand.h"
#include "document/decidesuggestioncommand.h"
#include "document/document.h"
#include "document/projectsession.h"
#include "project/project.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QSet>

namespace rosarch {

Project ProjectSession::project() const
{
    Project p = m_project;
    p.launch = m_launchOptions;
    p.workspace = m_projectPath.isEmpty()
                      ? QString()
                      : ProjectFile::workspaceField(m_projectPath, m_document->workspaceRoot());
    p.decisions = keyedDecisions();
    std::sort(p.decisions.begin(), p.decisions.end(),
              [](const auto &a, const auto &b) { return a.key() < b.key(); });
    return p;
}

bool ProjectSession::isUntitled() const
{
    return m_projectPath.isEmpty() && !m_document->workspaceRoot().isEmpty();
}

void ProjectSession::load()
{
    m_project = {};
    m_unsaved = false;
    m_modifiedOutside = false;
    m_migrationPending = false;
    const bool chosen = m_chosenProject && m_chosenProject->first == m_document->workspaceRoot();
    setProjectPath(chosen ? m_chosenProject->second
                          : ProjectFile::locate(m_document->workspaceRoot()));
    QList<SuggestionDecision> keyed;
    const QString legacy = m_document->workspaceRoot().isEmpty() || chosen
                               ? QString()
                               : DecisionStore::path(m_document->workspaceRoot());
    if (!m_projectPath.isEmpty() && QFileInfo::exists(m_projectPath)) {
        QString error;
        if (ProjectFile::read(m_projectPath, &m_project, &error)) {
            keyed = m_project.decisions;
        } else {
            // kept under another name before anything is written over it
            const QString kept = ProjectFile::keepUnreadable(m_projectPath);
            Q_EMIT loadFailed(kept.isEmpty()
                                  ? error
                                  : QCoreApplication::translate("rosarch::Document",
                                                                "%1\nThe file was kept as %2.")
                                        .arg(error, kept));
        }
    } else if (!legacy.isEmpty() && QFileInfo::exists(legacy)) {
        // Decisions of an earlier version, by position: taken over once, by the ids of the
        // model they are opened with (not an empty one), then written as the project and the
        // old file set aside.
        m_migrationPending = m_document->atomicNodes().nodes.isEmpty();
        if (!m_migrationPending) {
            const StableKeys keys(Recovery{m_document->atomicNodes(),
                                           m_document->launchDependencies(),
                                           m_document->architecture()});
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
        save(); // migrated: on disk as the old file was
}

void ProjectSession::markChanged()
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

bool ProjectSession::isModified() const
{
    return m_modifiedOutside || !m_document->undoStack()->isClean();
}

void ProjectSession::updateModified()
{
    const bool modified = isModified();
    if (modified == m_modifiedShown)
        return;
    m_modifiedShown = modified;
    Q_EMIT modifiedChanged(modified);
}

void ProjectSession::setProjectPath(const QString &path)
{
    if (path == m_projectPath)
        return;
    m_projectPath = path;
    Q_EMIT projectPathChanged(path);
}

QString ProjectSession::autosaveFile() const
{
    if (m_document->workspaceRoot().isEmpty())
        return {};
    // A new project never saved keeps its changes where the workspace's project would.
    return ProjectFile::autosavePath(
        m_projectPath.isEmpty() ? ProjectFile::locate(m_document->workspaceRoot()) : m_projectPath);
}

bool ProjectSession::writeAutosave()
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
    p.workspace = ProjectFile::workspaceField(side, m_document->workspaceRoot());
    QString error;
    if (!ProjectFile::write(side, p, &error)) {
        // kept in memory; the next change, save or close tries again
        Q_EMIT saveFailed(
            QCoreApplication::translate("rosarch::Document", "autosave: %1").arg(error));
        return false;
    }
    m_unsaved = false;
    return true;
}

bool ProjectSession::save()
{
    if (m_document->workspaceRoot().isEmpty()) { // no workspace: nothing to keep them with
        m_autosave.stop();
        m_unsaved = false;
        return true;
    }
    if (m_projectPath.isEmpty())
        return false; // a new project: saveProjectAs
    return saveAs(m_projectPath);
}

bool ProjectSession::saveAs(const QString &file)
{
    m_autosave.stop();
    Project p = project();
    p.workspace = ProjectFile::workspaceField(file, m_document->workspaceRoot());
    QString error;
    if (!ProjectFile::write(file, p, &error)) {
        Q_EMIT saveFailed(error); // kept in memory and modified
        if (m_unsaved)
            m_autosave.start();
        return false;
    }
    if (const QString side = autosaveFile(); !side.isEmpty())
        QFile::remove(side);
    if (file != ProjectFile::locate(m_document->workspaceRoot()))
        m_chosenProject = std::make_pair(m_document->workspaceRoot(), file);
    setProjectPath(file);
    QFile::remove(autosaveFile());
    m_unsaved = false;
    m_modifiedOutside = false;
    m_document->undoStack()->setClean();
    updateModified();
    return true;
}

void ProjectSession::discardChanges()
{
    m_autosave.stop();
    discardAutosave();
    m_unsaved = false;
    m_modifiedOutside = false;
    m_document->undoStack()->setClean();
    updateModified();
}

void ProjectSession::discardAutosave()
{
    if (const QString side = autosaveFile(); !side.isEmpty())
        QFile::remove(side);
}

bool ProjectSession::recoverAutosave(QString *error)
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

void ProjectSession::setProjectFile(const QString &workspaceRoot, const QString &file)
{
    m_chosenProject = std::make_pair(workspaceRoot, file);
    if (!workspaceRoot.isEmpty() && workspaceRoot == this->m_document->workspaceRoot())
        reloadWith([this] { load(); });
}

void ProjectSession::reloadWith(const std::function<void()> &load)
{
    const LaunchOptions before = m_launchOptions;
    DocumentChange change{DocumentChange::Model | DocumentChange::Decisions, {}};
    Q_EMIT m_document->aboutToChange(change);
    m_autosave.stop();
    m_document->dropAccepted();
    m_document->setDescriptions(m_document->analysisDescriptions());
    m_modifiedOutside = false;
    m_document->undoStack()->clear();
    load();
    if (m_launchOptions != before)
        change.parts |= DocumentChange::LaunchOptions;
    updateModified();
    Q_EMIT m_document->changed(change);
    if (hasSuggestionReport()) {
        SuggestionReport report = m_suggestionReport; // statuses from this project's decisions
        setSuggestions(std::move(report));
    }
}

} // namespace rosarch
