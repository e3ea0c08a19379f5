#include "app/commands/workspacerun.h"
#include "pipeline/stageprocess.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QCryptographicHash>
#include <QFile>
#include <QFileInfo>

namespace rosarch {

void WorkspaceRun::addOptions(QCommandLineParser &parser) const
{
    parser.addOption(m_argOption);
    parser.addOption(m_rootOption);
    parser.addOption(m_noDecisionsOption);
    parser.addOption(m_projectOption);
    parser.addOption(m_inProcessOption);
    parser.addOption(m_noCacheOption);
}

bool WorkspaceRun::read(const QCommandLineParser &parser, const QString &command, QString *error)
{
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2) {
        *error =
            QCoreApplication::translate("rosarch::CommandLine", "%1 needs one workspace folder.")
                .arg(command);
        return false;
    }
    m_workspace = positional.at(1);
    if (!QFileInfo(m_workspace).isDir()) {
        *error = QCoreApplication::translate("rosarch::CommandLine", "Not a folder: %1")
                     .arg(m_workspace);
        return false;
    }
    m_inProcess = parser.isSet(m_inProcessOption);
    if (parser.isSet(m_noCacheOption)) // read by this process's cache and the worker's
        qputenv("ROSARCH_NO_CACHE", "1");
    m_launch = {};
    m_launch.rootFile = parser.value(m_rootOption);
    for (const QString &arg : parser.values(m_argOption)) {
        const qsizetype sep = arg.indexOf(QLatin1String(":="));
        if (sep <= 0) {
            *error = QCoreApplication::translate("rosarch::CommandLine",
                                                 "--launch-arg expects name:=value, got '%1'.")
                         .arg(arg);
            return false;
        }
        m_launch.arguments.insert(arg.left(sep), arg.mid(sep + 2));
    }
    if (parser.isSet(m_noDecisionsOption) && parser.isSet(m_projectOption)) {
        *error = QCoreApplication::translate("rosarch::CommandLine",
                                             "--no-decisions and --project exclude each other.");
        return false;
    }
    m_projectFile = parser.isSet(m_noDecisionsOption) ? QString()
                    : parser.isSet(m_projectOption)   ? parser.value(m_projectOption)
                                                      : ProjectFile::locate(m_workspace);
    if (parser.isSet(m_projectOption) && !QFileInfo(m_projectFile).isFile()) {
        *error = QCoreApplication::translate("rosarch::CommandLine", "No such file: %1")
                     .arg(m_projectFile);
        return false;
    }
    if (!parser.isSet(m_projectOption) && !QFileInfo(m_projectFile).isFile())
        m_projectFile.clear(); // the workspace has no project (yet)
    m_project = {};
    if (!m_projectFile.isEmpty()) {
        if (!readProject(m_projectFile, &m_project, error))
            return false;
        // the command line's launch root and arguments win over the project's
        if (m_launch.rootFile.isEmpty())
            m_launch.rootFile = m_project.launch.rootFile;
        for (auto it = m_project.launch.arguments.cbegin(); it != m_project.launch.arguments.cend();
             ++it)
            if (!m_launch.arguments.contains(it.key()))
                m_launch.arguments.insert(it.key(), it.value());
        m_launch.externals = m_project.launch.externals; // the project's declarations
    }
    return true;
}

bool WorkspaceRun::readProject(const QString &file, Project *project, QString *error)
{
    QString why;
    if (ProjectFile::read(file, project, &why))
        return true;
    *error = QCoreApplication::translate("rosarch::CommandLine", "The project cannot be used: %1")
                 .arg(why);
    return false;
}

Recovery WorkspaceRun::recovered(const QString &workspace, const LaunchOptions &launch,
                                 bool inProcess, QString *failure, QByteArray *replyDigest)
{
    if (!inProcess && !StageProcess::helperPath().isEmpty()) {
        StageProcess::Result r =
            StageProcess::recover(workspace, launch, StageControl(), StageProcess::Options());
        if (!r.error.isEmpty()) {
            if (failure)
                *failure = r.error;
            return {};
        }
        if (replyDigest)
            *replyDigest = r.replyDigest;
        return std::move(r.recovery);
    }
    Recovery recovery = recoverWorkspace(workspace, launch);
    if (!inProcess)
        recovery.nodes.diagnostics.append(StageProcess::missingWorker());
    return recovery;
}

Recovery WorkspaceRun::recover(int *applied, QString *failure, QList<Orphan> *orphans,
                               QByteArray *madeFrom) const
{
    QString why;
    QByteArray reply;
    Recovery recovery = recovered(m_workspace, m_launch, m_inProcess, &why, &reply);
    if (madeFrom) {
        madeFrom->clear();
        QFile project(m_projectFile);
        if (!reply.isEmpty() && (m_projectFile.isEmpty() || project.open(QIODevice::ReadOnly)))
            *madeFrom = reply + QCryptographicHash::hash(
                                    m_projectFile.isEmpty() ? QByteArray() : project.readAll(),
                                    QCryptographicHash::Sha1);
    }
    if (!why.isEmpty()) {
        if (failure)
            *failure = why;
        return {};
    }
    // The model as corrected, exactly as the GUI exports it for the same project.
    CorrectedRecovery corrected = CorrectedModel::apply(recovery, m_project);
    if (applied) {
        int accepted = 0;
        for (const SuggestionDecision &d : std::as_const(corrected.decisions))
            accepted += d.status == Suggestion::Status::Accepted ? 1 : 0;
        *applied = accepted + int(m_project.corrections.size());
        for (const Orphan &o : std::as_const(corrected.orphans))
            *applied -= o.source == Orphan::Source::Correction ? 1 : 0;
    }
    if (orphans)
        *orphans = corrected.orphans;
    return std::move(corrected.recovery);
}

} // namespace rosarch
