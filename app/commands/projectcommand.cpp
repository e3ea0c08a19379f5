#include "app/commands/projectcommand.h"
#include "app/commands/commandline.h"
#include "app/commands/terminalstream.h"
#include "app/commands/workspacerun.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>
#include <QTextStream>

namespace rosarch {

namespace {

constexpr int kProjectUnreadable = 3;

QString usage()
{
    return QCoreApplication::translate("rosarch::CommandLine",
                                       "Usage: rosarch project check <project file> <workspace> "
                                       "[--in-process]\n");
}

} // namespace

QString ProjectCommand::describe(const Orphan &orphan, const QString &file)
{
    const QString what =
        orphan.source == Orphan::Source::Correction
            ? QCoreApplication::translate("rosarch::CommandLine", "correction %1 (%2)")
                  .arg(orphan.id, orphan.kind)
            : QCoreApplication::translate("rosarch::CommandLine", "decision (%1) on %2")
                  .arg(orphan.kind, orphan.target);
    return QCoreApplication::translate("rosarch::CommandLine",
                                       "%1: warning: orphaned %2: %3; it said: %4")
        .arg(file, what, orphan.reason, orphan.said);
}

int ProjectCommand::run(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "rosarch::CommandLine",
        "List the decisions and corrections of a project that no longer match the workspace."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("project"), QString());
    parser.addPositionalArgument(QStringLiteral("check"), QString());
    parser.addPositionalArgument(
        QStringLiteral("file"),
        QCoreApplication::translate("rosarch::CommandLine", "The project file."));
    parser.addPositionalArgument(
        QStringLiteral("workspace"),
        QCoreApplication::translate("rosarch::CommandLine", "The workspace folder."));
    const QCommandLineOption inProcess(
        QStringLiteral("in-process"),
        QCoreApplication::translate("rosarch::CommandLine",
                                    "Run the stages in this process instead of the analysis "
                                    "worker."));
    parser.addOption(inProcess);
    if (const int done = CommandLine::parseOrFinish(parser, arguments, usage()); done >= 0)
        return done;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 4 || positional.at(1) != QLatin1String("check")) {
        err << QCoreApplication::translate("rosarch::CommandLine",
                                           "project takes one subcommand, check, with a project "
                                           "file and a workspace.\n")
            << usage();
        return CommandLine::UsageError;
    }
    const QString &file = positional.at(2);
    const QString &workspace = positional.at(3);
    if (!QFileInfo(workspace).isDir()) {
        err << QCoreApplication::translate("rosarch::CommandLine", "Not a folder: %1\n")
                   .arg(workspace)
            << usage();
        return CommandLine::UsageError;
    }
    Project project;
    QString error;
    if (!WorkspaceRun::readProject(file, &project, &error)) {
        err << error << '\n';
        return kProjectUnreadable;
    }
    QString failure;
    const Recovery recovered =
        WorkspaceRun::recovered(workspace, project.launch, parser.isSet(inProcess), &failure);
    if (!failure.isEmpty()) {
        err << failure << '\n';
        return CommandLine::AnalysisErrors;
    }
    const CorrectedRecovery corrected = CorrectedModel::apply(recovered, project);
    for (const Orphan &o : corrected.orphans)
        out << describe(o, file) << '\n';
    out << QCoreApplication::translate("rosarch::CommandLine",
                                       "%1 decisions and %2 corrections; %3 orphaned.\n")
               .arg(project.decisions.size())
               .arg(project.corrections.size())
               .arg(corrected.orphans.size());
    return corrected.orphans.isEmpty() ? int(CommandLine::Ok) : int(CommandLine::AnalysisErrors);
}

} // namespace rosarch
