#include "app/commands/exportcommand.h"
#include "app/commands/commandline.h"
#include "app/commands/terminalstream.h"
#include "app/commands/workspacerun.h"
#include "artifacts/nodlwriter.h"
#include "core/visibletext.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>

namespace rosarch {

namespace {

QString usage()
{
    return QCoreApplication::translate("rosarch::CommandLine",
                                       "Usage: rosarch export nodl <workspace> --out <dir> "
                                       "[--quiet] [--no-decisions | --project <file>] "
                                       "[--in-process] [--no-cache]\n");
}

} // namespace

int ExportCommand::run(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "rosarch::CommandLine",
        "Write the recovered node classes of a ROS 2 workspace as NoDL documents (Node "
        "Definition Language v2), one per class: <dir>/<package>/<executable>.nodl.json."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("export"), QString());
    parser.addPositionalArgument(
        QStringLiteral("workspace"),
        QCoreApplication::translate("rosarch::CommandLine", "The workspace folder to analyse."));
    const QCommandLineOption outOption(
        QStringList{QStringLiteral("o"), QStringLiteral("out")},
        QCoreApplication::translate("rosarch::CommandLine", "Folder for the documents."),
        QStringLiteral("dir"));
    const QCommandLineOption quietOption(
        QStringList{QStringLiteral("q"), QStringLiteral("quiet")},
        QCoreApplication::translate("rosarch::CommandLine",
                                    "Do not list what NoDL cannot express."));
    parser.addOption(outOption);
    parser.addOption(quietOption);
    WorkspaceRun run;
    run.addOptions(parser);

    // The format comes right after the command; the rest is parsed as `recover` parses its
    // arguments, so that WorkspaceRun reads the workspace and the project the same way.
    const QString format = arguments.value(2);
    QStringList rest = arguments;
    if (format.startsWith(u'-')) {
        if (const int done = CommandLine::parseOrFinish(parser, arguments, usage()); done >= 0)
            return done; // --help, or an option before the format
    } else if (!format.isEmpty()) {
        rest.removeAt(2);
    }
    if (format != QLatin1String("nodl")) {
        err << (format.isEmpty() || format.startsWith(u'-')
                    ? QCoreApplication::translate("rosarch::CommandLine",
                                                  "export needs a format: nodl.\n")
                    : QCoreApplication::translate("rosarch::CommandLine",
                                                  "Unknown export format '%1'; rosarch exports "
                                                  "nodl.\n")
                          .arg(format))
            << usage();
        return CommandLine::UsageError;
    }
    if (const int done = CommandLine::parseOrFinish(parser, rest, usage()); done >= 0)
        return done;
    QString problem;
    if (!parser.isSet(outOption))
        problem = QCoreApplication::translate("rosarch::CommandLine", "export needs --out <dir>.");
    if (!problem.isEmpty() || !run.read(parser, QStringLiteral("export nodl"), &problem)) {
        err << problem << "\n\n" << usage();
        return CommandLine::UsageError;
    }

    QString failure;
    const Recovery recovery = run.recover(nullptr, &failure);
    if (!failure.isEmpty()) {
        err << failure << '\n';
        return CommandLine::AnalysisErrors;
    }
    const NodlWriter::Documents nodl = NodlWriter::write(recovery.nodes);
    QString error;
    if (!NodlWriter::writeTo(nodl, parser.value(outOption), &error)) {
        err << error << '\n';
        return CommandLine::AnalysisErrors;
    }
    if (!parser.isSet(quietOption))
        for (const QString &line : nodl.omitted)
            err << "note: " << visibleText(line) << '\n';
    out << QCoreApplication::translate("rosarch::CommandLine",
                                       "Wrote %1 NoDL documents to %2 (%3 notes on what NoDL "
                                       "cannot express).\n")
               .arg(nodl.files.size())
               .arg(QDir::toNativeSeparators(QDir(parser.value(outOption)).absolutePath()))
               .arg(nodl.omitted.size());
    return CommandLine::Ok;
}

} // namespace rosarch
