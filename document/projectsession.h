#pragma once

#include "accepted/suggestiondecision.h"
#include "core/subsystemgroup.h"
#include "core/suggestion.h"
#include "document/documentchange.h"
#include "launch/launchanalyzer.h"
#include "project/correctedmodel.h"
#include "project/project.h"
#include "project/stablekeys.h"
#include "suggestions/suggestionreport.h"

#include <QFuture>
#include <QFutureWatcher>
#include <QHash>
#include <QMap>
#include <QObject>
#include <QTimer>

#include <functional>
#include <optional>

namespace rosarch {

class Document;

/// What a person made of the open recovery, and its file: the project. It holds the
/// suggestions of the last run and the decisions on them, the corrections, the finding marks
/// and the launch options; it binds them to the model by stable key whenever the Document's
/// model is replaced; and it keeps the project file: load, migration of old decision files,
/// save, save-as, the autosave side file and what a crash left in it.
///
/// Every change is an undoable command on the Document's undo stack and is announced by the
/// Document's `changed` signal, so views follow one signal. The file is written when a person
/// saves; until then changes are modified state, kept a few seconds after they happen in the
/// autosave side file (ProjectFile::autosavePath), also before another workspace replaces them
/// and when the session ends, so a crash loses at most that much.
class ProjectSession : public QObject
{
    Q_OBJECT
public:
    /// The session of `document`, which owns it.
    explicit ProjectSession(Document *document);
    /// Writes the autosave side file when a change is not in it.
    ~ProjectSession() override;

    // Launch options: what stage 2 runs with, kept in the project.

    /// The root launch file and argument values stage 2 runs with (a person's choice).
    const LaunchOptions &launchOptions() const { return m_launchOptions; }
    /// Stores what the next stage 2 run uses (a change of the project); it does not run
    /// anything.
    void setLaunchOptions(const LaunchOptions &options);
    /// Launch options a project that has none starts from (remembered in the settings before
    /// projects held them): used like setLaunchOptions, but not a change of the project.
    void adoptLaunchOptions(const LaunchOptions &options);

    // Suggestions and decisions. Decisions are kept in the project by key and applied again
    // whenever the model or the suggestions are replaced.

    /// The last suggestion run, each suggestion with its current status.
    const SuggestionReport &suggestionReport() const { return m_suggestionReport; }
    const QList<Suggestion> &suggestions() const { return m_suggestionReport.suggestions; }
    /// The suggestion with `id`, or null.
    const Suggestion *suggestion(const QString &id) const;
    /// Replaces the suggestions with a new run's. Suggestions whose subject and proposal were
    /// decided before get that status; accepted descriptions are applied again. Returns how
    /// many were already decided.
    int setSuggestions(SuggestionReport report);
    /// Pushes an undoable accept; false when there is no such suggestion or it is accepted.
    bool acceptSuggestion(const QString &id);
    /// Pushes an undoable reject; false when there is no such suggestion or it is rejected.
    bool rejectSuggestion(const QString &id);
    /// Accepts every pending suggestion of `kind` as one undo step; returns how many.
    int acceptAllSuggestions(Suggestion::Kind kind);
    /// Every decision of this project, by SuggestionDecision::key.
    const QMap<QString, SuggestionDecision> &decisions() const { return m_decisions; }
    /// Accepted subsystem groupings whose root and members exist in the current model.
    QList<SubsystemGroup> acceptedGroupings() const;
    /// Accepted values of unresolved items that exist in the current model: item id → value.
    QMap<QString, QString> acceptedNames() const;

    // Corrections (blueprint §5): a person's edits of the model, kept in the project by stable
    // key and applied by CorrectedModel; Document::accepted() shows them.

    /// The corrections of the project, in the order they were made.
    const QList<Correction> &corrections() const { return m_project.corrections; }
    /// The correction with `id`, or null.
    const Correction *correction(const QString &id) const { return m_project.correction(id); }
    /// Pushes an undoable correction. Its id, author and time are filled in when empty; returns
    /// the id, or "" when the target is not an element of the current model (nothing pushed).
    QString addCorrection(Correction correction);
    /// Pushes an undoable removal of correction `id`, which reverts what it changed; false when
    /// there is none.
    bool removeCorrection(const QString &id);
    /// Several corrections as one undo step (e.g. a group of edits); returns the ids pushed.
    QStringList addCorrections(const QList<Correction> &corrections, const QString &text);
    /// Pushes an undoable change of a node's description: a correction (`describe`) kept in
    /// the project, so re-running the stages keeps it.
    void setNodeDescription(const QString &nodeId, const QString &description);
    /// Decisions and corrections of the project that match nothing in the current model.
    const QList<Orphan> &orphans() const;
    /// Who makes corrections here: $ROSARCH_AUTHOR, else the login name.
    static QString author();

    // Findings: diagnostics a person hid or accepted, kept in the project by key.

    /// The marks of the project, sorted by finding key.
    const QList<FindingMark> &findingMarks() const { return m_project.findings; }
    /// Pushes one undoable step that gives the findings `keys` the `status` (with `reason`,
    /// the author and the time); returns how many marks changed.
    int markFindings(const QStringList &keys, FindingMark::Status status,
                     const QString &reason = {});
    /// Pushes one undoable step that removes the marks of `keys` (the findings show again and
    /// count as new); returns how many marks were removed.
    int unmarkFindings(const QStringList &keys);

    // Stable keys (blueprint §5): how the project names the elements of the model.

    /// The stable key of an element by the id the views use ("arc_3", "arc_3/p1", "n3", "lf2",
    /// "lf1/part2", "topic:/scan"); "" when there is no such element in the model as recovered.
    QString keyOf(const QString &id) const;
    /// The stable keys of the model as recovered. Made once per model, on a thread of their
    /// own as soon as the model arrives (a large model's keys take a few hundred ms); waits
    /// for that when they are not made yet.
    const StableKeys &recoveredKeys() const;
    /// True when recoveredKeys() and keyOf() answer without waiting.
    bool keysReady() const;

    // The project file.

    /// The project file ("" without a workspace and for a new project never saved): the one
    /// opened, else the workspace's own rosarch.project.json, else the one kept for it under
    /// the application data.
    QString projectPath() const { return m_projectPath; }
    /// The project as it would be saved now: decisions by stable key (those that match
    /// nothing in this model kept as they were), corrections, launch options.
    Project project() const;
    /// True while the project differs from its file: a change since the last save or load that
    /// undo has not taken back.
    bool isModified() const;
    /// True for a new project of a workspace that was never saved (Save asks where).
    bool isUntitled() const;
    /// True while a change is not in the autosave side file yet (the autosave is pending).
    bool hasAutosavePending() const { return m_unsaved; }
    /// Saves the project to its file (projectPath()) and removes the autosave side file; false
    /// when writing failed (then saveFailed says why; the changes stay in memory and
    /// modified) or the project has no file yet (a new project: saveAs).
    bool save();
    /// Saves the project to `file`, which becomes its file (a `workspace` field says where the
    /// workspace is when the file is not in it); false as save.
    bool saveAs(const QString &file);
    /// Makes `file` the project of `workspaceRoot` ("" = a new, empty project never saved); read
    /// now when that workspace is open (its undo history cleared), else when it opens.
    void setProjectFile(const QString &workspaceRoot, const QString &file);
    /// Forgets that the project is modified and removes its autosave side file: a person chose
    /// to discard the changes (the window closes or another project replaces this one).
    void discardChanges();

    // The autosave side file.

    /// How long after the first change the autosave writes the side file (default 2 s): later
    /// changes do not postpone it, so a crash loses at most this much.
    void setAutosaveInterval(int milliseconds) { m_autosave.setInterval(milliseconds); }
    /// Writes the autosave side file now if a change is not in it (removes it when the project
    /// is back to its saved state); false when it could not be written (saveFailed).
    bool writeAutosave();
    /// The autosave side file of this project ("" without a workspace).
    QString autosaveFile() const;
    /// Replaces the project with the autosave side file's, as modified state (what a crash left
    /// behind); false with `error` when it cannot be read (the side file stays).
    bool recoverAutosave(QString *error);
    /// Removes the autosave side file (a person chose not to recover it).
    void discardAutosave();

    /// What a decision touches, captured for undo: the stored decision of one subject and
    /// proposal.
    struct DecisionSnapshot
    {
        QString key;
        std::optional<SuggestionDecision> decision; ///< none = pending
        bool operator==(const DecisionSnapshot &) const = default;
    };

Q_SIGNALS:
    /// The project could not be written; `message` says where and why.
    void saveFailed(const QString &message);
    /// The project file could not be read; `message` says which file, why, and where the
    /// unreadable file was kept.
    void loadFailed(const QString &message);
    /// The project became modified or was saved (or its changes undone or discarded).
    void modifiedChanged(bool modified);
    /// The project's file changed (saved under another name, another project opened).
    void projectPathChanged(const QString &path);
    /// The keys of the model as recovered were made (keysReady() is true now).
    void keysMade();

private:
    friend class Document; // replaces the model: beginReplace, endReplace
    friend class DecideSuggestionCommand;
    friend class CorrectionCommand;
    friend class FindingMarkCommand;

    /// What the project carries over a replacement of the model, by the old model's keys.
    struct Carried
    {
        bool sameWorkspace = false;
        QList<SuggestionDecision> decisions;
        QList<Suggestion> suggestions;
        LaunchOptions launchOptions;
        bool hadSuggestions = false;
    };
    /// Before the Document replaces the model (`all`: stages 1-3 of `workspaceRoot`, else
    /// stages 2 and 3): the decisions and suggestions by the keys of the model going away.
    Carried beginReplace(bool all, const QString &workspaceRoot);
    /// After the Document replaced the model: the project bound to it again (read when the
    /// workspace is another), the new model's keys started. Returns the parts that changed
    /// besides the model.
    DocumentChange::Parts endReplace(bool all, const Carried &carried);
    /// Drops the keys of the model going away (a job still making them is left to finish).
    void dropKeys();

    // the commands' steps
    void replaceFindingMarks(const QList<std::pair<QString, std::optional<FindingMark>>> &marks);
    void insertCorrection(int index, const Correction &correction);
    void takeCorrection(const QString &id);
    DecisionSnapshot snapshot(const Suggestion &suggestion) const;
    DecisionSnapshot decided(const Suggestion &suggestion, Suggestion::Status status) const;
    void restore(const DecisionSnapshot &snapshot);

    /// `correction` made ready to push: id, author, time; false when its target is unknown.
    bool prepare(Correction *correction, int offset) const;
    /// Sets every node's description to what analysis, accepted suggestions and `describe`
    /// corrections say, in that order; returns the ids of the nodes that changed (no signals).
    QStringList refreshDescriptions();
    /// Reads the workspace's project and applies the accepted descriptions (no signals).
    void load();
    /// The decisions by stable key, with this model's keys (those bound nowhere included).
    QList<SuggestionDecision> keyedDecisions() const;
    /// Binds decisions stored by key to this model's ids; what matches nothing is kept apart.
    void bindDecisions(const QList<SuggestionDecision> &keyed);
    /// The suggestions with their subjects as stable keys of this model (unknown ones left out).
    QList<Suggestion> keyedSuggestions() const;
    /// Puts back suggestions keyed by keyedSuggestions() on this model's ids, with the status
    /// the decisions give; those whose subject is gone are dropped.
    void bindSuggestions(const QList<Suggestion> &keyed);
    bool hasSuggestionReport() const;
    void markChanged();
    /// Replaces the project in memory by what `load` puts there (descriptions as analysis
    /// found them, undo history cleared, the suggestions' statuses from its decisions).
    void reloadWith(const std::function<void()> &load);
    void updateModified();
    void setProjectPath(const QString &path);
    /// Makes the keys of the model as recovered (the model changed): a large model's on their
    /// own thread, a small one's at once. A job still making the old ones is left to finish
    /// and be dropped.
    void startKeys();
    /// The model's corrections, decisions or descriptions changed: announces `parts` (and the
    /// nodes whose descriptions changed) through the Document.
    void announce(DocumentChange::Parts parts, const QString &id = {});

    Document *m_document;
    LaunchOptions m_launchOptions;
    SuggestionReport m_suggestionReport;
    QMap<QString, SuggestionDecision> m_decisions; ///< bound to this model's ids
    Project m_project;     ///< as read; decisions are rebuilt from m_decisions when saved
    QString m_projectPath; ///< where m_project is kept
    QList<SuggestionDecision> m_unboundDecisions; ///< by key: nothing here matches them
    mutable std::optional<StableKeys> m_keys;     ///< keyOf(): of the model as recovered
    mutable QFuture<StableKeys> m_keysJob;        ///< making m_keys, until taken
    QFutureWatcher<StableKeys> m_keysWatcher;
    QTimer m_autosave;
    bool m_unsaved = false;          ///< a change is not in the autosave side file
    bool m_modifiedOutside = false;  ///< modified by what the undo stack does not hold
    bool m_modifiedShown = false;    ///< as last announced by modifiedChanged
    bool m_migrationPending = false; ///< old decisions.json waits for a model to key them by
    /// The project file a person chose for a workspace (setProjectFile): workspace → file.
    std::optional<std::pair<QString, QString>> m_chosenProject;
};

} // namespace rosarch
