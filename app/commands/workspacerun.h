#pragma once

#include "acceptedmodel.h"
#include "recovery.h"

#include <QCommandLineOption>
#include <QStringList>

class QCommandLineParser;

namespace rosarch {

/// What `recover` and `check` share: the workspace argument, launch arguments, the launch
/// root and the decisions to apply (the workspace's own, a given file, or none); and the
/// recovery they ask for, as accepted.
class WorkspaceRun
{
public:
    /// Adds the options to `parser`.
    void addOptions(QCommandLineParser &parser) const;
    /// Reads them from a parsed `parser` whose positional arguments are the command and the
    /// workspace. False with a message (a usage error) when they are wrong.
    bool read(const QCommandLineParser &parser, const QString &command, QString *error);

    /// Runs the stages, in the analysis worker unless --in-process, and applies the decisions;
    /// `applied` counts them. When the worker stops without a result (outside any one file's
    /// analysis), `failure` says why and the recovery is empty.
    Recovery recover(int *applied = nullptr, QString *failure = nullptr) const;
    const QString &workspace() const { return m_workspace; }

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
        QStringLiteral("Use the model as recovered, without the decisions a person made on this "
                       "workspace in the GUI.")};
    QCommandLineOption m_projectOption{
        QStringLiteral("project"),
        QStringLiteral("Apply the decisions in this file (a decisions.json the GUI saved) "
                       "instead of the workspace's own."),
        QStringLiteral("file")};
    QCommandLineOption m_inProcessOption{
        QStringLiteral("in-process"),
        QStringLiteral("Run the stages in this process instead of the analysis worker "
                       "(rosarch-stages): faster to debug, but a crash in analysis ends the "
                       "command and the per-file time and memory budgets do not apply.")};
    QString m_workspace;
    LaunchOptions m_launch;
    bool m_inProcess = false;
    QString m_decisions; ///< the decisions file ("" = none)
};

} // namespace rosarch
