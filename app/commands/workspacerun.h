#pragma once

#include "pipeline/recovery.h"
#include "project/correctedmodel.h"

#include <QCommandLineOption>
#include <QStringList>

class QCommandLineParser;

namespace rosarch {

/// What `recover` and `check` share: the workspace argument, launch arguments, the launch
/// root and the project to apply (the workspace's own rosarch.project.json, a given file, or
/// none); and the recovery they ask for, as corrected (CorrectedModel, as the GUI exports it).
class WorkspaceRun
{
public:
    /// Adds the options to `parser`.
    void addOptions(QCommandLineParser &parser) const;
    /// Reads them from a parsed `parser` whose positional arguments are the command and the
    /// workspace. False with a message (a usage error) when they are wrong.
    bool read(const QCommandLineParser &parser, const QString &command, QString *error);

    /// Runs the stages, in the analysis worker unless --in-process, and applies the project;
    /// `applied` counts its accepted decisions and corrections, `orphans` gets what matched
    /// nothing. When the worker stops without a result (outside any one file's analysis),
    /// `failure` says why and the recovery is empty.
    /// `madeFrom` gets a digest of what decided the result (the worker's reply and the project
    /// file), for ArtifactWriter to know unchanged artifacts cheaply; "" when there is none.
    Recovery recover(int *applied = nullptr, QString *failure = nullptr,
                     QList<Orphan> *orphans = nullptr, QByteArray *madeFrom = nullptr) const;
    const QString &workspace() const { return m_workspace; }
    /// The project applied (empty without one).
    const Project &project() const { return m_project; }
    /// The project file applied ("" = none).
    const QString &projectFile() const { return m_projectFile; }

    /// Runs stages 1 to 3 on `workspace` as recovered (no project), in the analysis worker
    /// unless `inProcess`; `failure` as for recover().
    static Recovery recovered(const QString &workspace, const LaunchOptions &launch, bool inProcess,
                              QString *failure, QByteArray *replyDigest = nullptr);
    /// Reads the project `file`; false with a message naming the file when it cannot be used.
    static bool readProject(const QString &file, Project *project, QString *error);

private:
    QCommandLineOption m_argOption{QStringLiteral("launch-arg"),
                                   QStringLiteral("Set a launch argument (repeatable)."),
                                   QStringLiteral("name:=value")};
    QCommandLineOption m_rootOption{
        QStringLiteral("launch-root"),
        QStringLiteral("Analyse only this launch file (relative to the workspace) as the root."),
        QStringLiteral("file")};
    QCommandLineOption m_noDecisionsOption{
        QStringLiteral("no-decisions"),
        QStringLiteral("Use the model as recovered, without the workspace's project (the "
                       "decisions and corrections a person made).")};
    QCommandLineOption m_projectOption{
        QStringLiteral("project"),
        QStringLiteral("Apply this project file instead of the workspace's own "
                       "rosarch.project.json."),
        QStringLiteral("file")};
    QCommandLineOption m_inProcessOption{
        QStringLiteral("in-process"),
        QStringLiteral("Run the stages in this process instead of the analysis worker "
                       "(rosarch-stages): faster to debug, but a crash in analysis ends the "
                       "command and the per-file time and memory budgets do not apply.")};
    QCommandLineOption m_noCacheOption{
        QStringLiteral("no-cache"),
        QStringLiteral("Analyse every file again, without reading or writing the analysis cache "
                       "(as ROSARCH_NO_CACHE=1 does).")};
    QString m_workspace;
    LaunchOptions m_launch;
    bool m_inProcess = false;
    QString m_projectFile; ///< the project file ("" = none)
    Project m_project;
};

} // namespace rosarch
