#pragma once

#include "accepted/suggestiondecision.h"
#include "launch/launchanalyzer.h"
#include "project/correction.h"
#include "project/findingmark.h"

#include <QByteArray>
#include <QList>
#include <QString>

namespace rosarch {

/// Everything a person decided about one workspace (blueprint §5): the launch root and
/// argument values, decisions on suggestions, corrections (review marks and groupings among
/// them). Every target is a stable key, every path workspace-relative. It never holds a secret.
struct Project
{
    /// The newest version this build reads and writes; files of a newer version are refused,
    /// not guessed at. A project is written as version 1 unless it uses what version 2 added
    /// (findings) or version 3 added (expected externals), so that older builds still read it.
    static constexpr int kVersion = 3;

    LaunchOptions launch;
    /// Where the workspace is, as the file says it: "" = the file's folder, else a path relative
    /// to that folder (a project kept inside the workspace) or an absolute one (kept elsewhere).
    QString workspace;
    /// Decisions on suggestions; targetId and memberIds hold stable keys (StableKeys), sorted by
    /// SuggestionDecision::key.
    QList<SuggestionDecision> decisions;
    QList<Correction> corrections; ///< in the order they were made
    /// Findings hidden or accepted (version 2), sorted by key; one mark per key.
    QList<FindingMark> findings;

    bool isEmpty() const
    {
        return launch == LaunchOptions{} && decisions.isEmpty() && corrections.isEmpty() &&
               findings.isEmpty();
    }
    /// "c<n>" one past the highest correction id in the project.
    QString nextCorrectionId() const;
    /// The correction with `id`, or null.
    const Correction *correction(const QString &id) const;
    /// The mark of the finding with `key`, or null.
    const FindingMark *finding(const QString &key) const;
    /// The version the file of this project needs: 3 when it declares expected externals, 2
    /// when it marks findings, else 1.
    int version() const { return !launch.externals.isEmpty() ? 3 : findings.isEmpty() ? 1 : 2; }
    bool operator==(const Project &) const = default;
};

/// The project file on disk: plain JSON with sorted keys, checked against
/// schemas/project.schema.json on load, written atomically.
namespace ProjectFile {
/// Where a workspace keeps its project by default: `<workspace>/rosarch.project.json`.
QString defaultPath(const QString &workspaceRoot);
/// The project of a workspace: its own rosarch.project.json when there is one, else the one
/// kept for it under the application data (`projects/<sha1 of the absolute path>/`).
QString locate(const QString &workspaceRoot);
/// Where the project of a workspace without its own file is kept under the application data.
QString appDataPath(const QString &workspaceRoot);
/// The `workspace` field for a project of `workspaceRoot` written to `file` ("" when the file
/// is in the workspace's top folder, relative when inside the workspace, else absolute).
QString workspaceField(const QString &file, const QString &workspaceRoot);
/// The workspace of the project `project` read from `file` (the field resolved against it).
QString workspaceOf(const QString &file, const Project &project);
/// The autosave side file of `file`: `.<name>.autosave` next to it.
QString autosavePath(const QString &file);
/// The schema (JSON Schema subset) every project file is checked against.
QJsonObject schema();

QByteArray toJson(const Project &project);
/// False with `error` (which says where and what) when `data` is not a project this build reads:
/// not JSON, against the schema, or of a newer version.
bool fromJson(const QByteArray &data, Project *project, QString *error);
/// Reads `file`; false with `error` naming the file when it cannot be read or is not a project.
bool read(const QString &file, Project *project, QString *error);
/// Writes atomically (QSaveFile); false with `error` naming the file and the reason.
bool write(const QString &file, const Project &project, QString *error);
/// Keeps a copy of a file that could not be read next to it (`<file>.unreadable-<time>`) so
/// that saving over it loses nothing; returns the copy's path ("" when copying failed).
QString keepUnreadable(const QString &file);
} // namespace ProjectFile

} // namespace rosarch
