#include "app/commands/commandline.h"
#include "app/commands/checkcommand.h"
#include "app/commands/diffcommand.h"
#include "app/commands/evalcommand.h"
#include "app/commands/exportcommand.h"
#include "app/commands/projectcommand.h"
#include "app/commands/sitecommand.h"
#include "app/commands/suggestcommand.h"
#include "app/commands/terminalstream.h"
#include "app/commands/workspacerun.h"
#include "artifacts/artifactwriter.h"
#include "core/editdistance.h"
#include "core/visibletext.h"
#include "pipeline/recovery.h"
#include "plantuml/plantumlrenderer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>

#include <algorithm>
#include <cstring>

namespace rosarch {

namespace {

const char *const kCommands[] = {
    "recover", "check", "diff", "eval", "suggest", "project", "export", "site",
};

QString usageText()
{
    return QCoreApplication::translate(
        "rosarch::CommandLine",
        "Usage:\n"
        "  rosarch [workspace]                       open the GUI (without a workspace: the "
        "last one, else the example)\n"
        "  rosarch recover <workspace> --out <dir> [--launch-arg name:=value]... [--launch-root "
        "<file>]\n"
        "                  [--no-decisions | --project <file>] [--render svg|png "
        "[--plantuml-jar <file>]]\n"
        "                  [--in-process] [--no-cache]\n"
        "                                            run the stages headless and write the "
        "artifacts, with\n"
        "                                            the project applied (default: the "
        "workspace's\n"
        "                                            rosarch.project.json, when there is one)\n"
        "  rosarch project check <project file> <workspace> [--in-process]\n"
        "                                            list the decisions and corrections that no "
        "longer\n"
        "                                            match anything (exit 0 none, 1 orphaned, 2 "
        "usage,\n"
        "                                            3 the project cannot be read)\n"
        "  rosarch check <workspace> [--format text|json|sarif|junit] [--output <file>]\n"
        "                [--baseline <file>] [--write-baseline <file>] [--fail-on "
        "error|warning|info|never]\n"
        "                                            report diagnostics and architecture checks "
        "for CI\n"
        "                                            (exit 0 pass, 1 new findings, 2 usage, 3 "
        "file error)\n"
        "  rosarch diff <before> <after> | <workspace> --rev A --rev B [--format text|json]\n"
        "                                            what changed between two recoveries "
        "(artifact\n"
        "                                            folders, workspaces or git revisions)\n"
        "  rosarch eval --reference <dir|file> --recovered <dir|file> [--level acd|ccd] [--json]\n"
        "                                            score recovered PlantUML diagrams against a "
        "reference\n"
        "  rosarch suggest <workspace> --out <dir> [--llm-endpoint URL] [--llm-model NAME] "
        "[--llm-timeout S]\n"
        "                                            write checked suggestions to "
        "suggestions.json\n"
        "                                            (deterministic only without an endpoint)\n"
        "  rosarch export nodl <workspace> --out <dir> [--no-decisions | --project <file>]\n"
        "                                            write each node class's parameters, topics, "
        "services and\n"
        "                                            actions as a NoDL document\n"
        "                                            (<dir>/<package>/<executable>.nodl.json)\n"
        "  rosarch site <workspace> --out <dir> [--title <text>] [--source-url <pattern>]\n"
        "                                            write the architecture as a static HTML "
        "site (systems,\n"
        "                                            diagrams, nodes, topics, launch files, "
        "findings, search)\n"
        "  rosarch --help | --version\n"
        "\n"
        "Artifacts written by recover: atomic_nodes.json, launch_dependencies.json, "
        "architecture.json,\n"
        "diagnostics.json, acd/<ClassName>.puml, ccd/<launch file stem>.puml,\n"
        "mermaid/<launch file stem>.md, graph/<root launch file stem>.dot (and .svg/.png next "
        "to each .puml with --render)\n"
        "recover and check run the stages in the analysis worker (rosarch-stages), which skips\n"
        "a file that crashes it or overruns its budget; --in-process runs them in the command.\n"
        "Per-file results are kept in the analysis cache (the user's cache folder, "
        "rosarch/analysis);\n"
        "--no-cache (or ROSARCH_NO_CACHE=1) analyses every file again.\n"
        "Exit codes: 0 ok, 1 analysis finished with errors reported, 2 usage error.\n");
}

int recover(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "rosarch::CommandLine",
        "Recover the architecture of a ROS 2 workspace and write the artifacts."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("recover"), QString());
    parser.addPositionalArgument(
        QStringLiteral("workspace"),
        QCoreApplication::translate("rosarch::CommandLine", "The workspace folder to analyse."));
    const QCommandLineOption outOption(
        QStringList{QStringLiteral("o"), QStringLiteral("out")},
        QCoreApplication::translate("rosarch::CommandLine", "Folder for the artifacts."),
        QStringLiteral("dir"));
    const QCommandLineOption quietOption(
        QStringList{QStringLiteral("q"), QStringLiteral("quiet")},
        QCoreApplication::translate("rosarch::CommandLine", "Print only errors."));
    const QCommandLineOption renderOption(
        QStringLiteral("render"),
        QCoreApplication::translate("rosarch::CommandLine",
                                    "Also render every ACD and CCD with PlantUML, as svg or png "
                                    "(needs Java and a PlantUML jar)."),
        QStringLiteral("svg|png"));
    const QCommandLineOption jarOption(
        QStringLiteral("plantuml-jar"),
        QCoreApplication::translate("rosarch::CommandLine",
                                    "The PlantUML jar for --render (default "
                                    "$ROSARCH_PLANTUML_JAR, or one installed with rosarch)."),
        QStringLiteral("file"));
    parser.addOption(outOption);
    parser.addOption(quietOption);
    parser.addOption(renderOption);
    parser.addOption(jarOption);
    WorkspaceRun run;
    run.addOptions(parser);
    if (const int done = CommandLine::parseOrFinish(parser, arguments, usageText()); done >= 0)
        return done;
    QString problem;
    if (!parser.isSet(outOption))
        problem = QCoreApplication::translate("rosarch::CommandLine", "recover needs --out <dir>.");
    const QString render = parser.value(renderOption).toLower();
    if (problem.isEmpty() && parser.isSet(renderOption) && render != QLatin1String("svg") &&
        render != QLatin1String("png"))
        problem = QCoreApplication::translate("rosarch::CommandLine",
                                              "--render takes svg or png, not '%1'.")
                      .arg(render);
    QString jar, java;
    if (problem.isEmpty() && parser.isSet(renderOption)) {
        // Known before the analysis runs: a missing renderer is a usage error, not a late one.
        jar = PlantUmlRenderer::findJar(parser.value(jarOption));
        if (parser.isSet(jarOption) && !QFileInfo(parser.value(jarOption)).isFile())
            jar.clear(); // the jar asked for, or none: never another one silently
        java = PlantUmlRenderer::findJava();
        QString why;
        if (!PlantUmlRenderer::render({}, render, jar, java, &why))
            problem = why;
    }
    if (!problem.isEmpty() || !run.read(parser, QStringLiteral("recover"), &problem)) {
        err << problem << "\n\n" << usageText();
        return CommandLine::UsageError;
    }
    const bool quiet = parser.isSet(quietOption);

    QElapsedTimer timer;
    timer.start();
    int decisions = 0;
    QString failure;
    QList<Orphan> orphans;
    QByteArray madeFrom;
    const Recovery recovery = run.recover(&decisions, &failure, &orphans, &madeFrom);
    const qint64 elapsed = timer.elapsed();
    if (!failure.isEmpty()) {
        err << failure << '\n'
            << QCoreApplication::translate("rosarch::CommandLine",
                                           "Nothing was written; earlier artifacts are unchanged.")
            << '\n';
        return CommandLine::AnalysisErrors;
    }

    QList<Diagnostic> diagnostics = recovery.nodes.diagnostics;
    diagnostics.append(recovery.launch.diagnostics);
    diagnostics.append(recovery.architecture.diagnostics);
    for (const Diagnostic &d : std::as_const(diagnostics)) {
        if (quiet && d.severity != Diagnostic::Severity::Error)
            continue;
        const QString where =
            d.evidence.file.isEmpty() ? QString()
            : d.evidence.line > 0
                ? QStringLiteral("%1:%2: ").arg(d.evidence.file).arg(d.evidence.line)
                : d.evidence.file + QStringLiteral(": ");
        // One line each, whatever the file name or message holds.
        err << visibleText(where) << Diagnostic::severityName(d.severity) << ": "
            << visibleText(d.message) << '\n';
    }
    for (const Orphan &o : std::as_const(orphans))
        err << ProjectCommand::describe(o, run.projectFile()) << '\n';
    QStringList written;
    QString error, notice;
    if (!ArtifactWriter::writeAll(recovery, parser.value(outOption), &written, &error, madeFrom,
                                  &notice)) {
        err << error << '\n';
        return CommandLine::AnalysisErrors;
    }
    if (!notice.isEmpty())
        err << "note: " << visibleText(notice) << '\n';
    int rendered = 0;
    if (parser.isSet(renderOption)) {
        QStringList diagrams;
        for (const QString &file : std::as_const(written))
            if (file.endsWith(QLatin1String(".puml")))
                diagrams << file;
        if (!PlantUmlRenderer::render(diagrams, render, jar, java, &error)) {
            err << QCoreApplication::translate("rosarch::CommandLine",
                                               "Rendering with PlantUML failed:\n%1\n")
                       .arg(error);
            return CommandLine::AnalysisErrors;
        }
        rendered = int(diagrams.size());
    }
    const RecoveryCounts counts = RecoveryCounts::of(recovery);
    if (!quiet) {
        if (rendered > 0)
            out << QCoreApplication::translate("rosarch::CommandLine",
                                               "Rendered %1 diagrams as %2 with PlantUML.\n")
                       .arg(rendered)
                       .arg(render);
        if (decisions > 0)
            out << QCoreApplication::translate("rosarch::CommandLine",
                                               "Applied %1 accepted decisions and corrections of "
                                               "%2 (--no-decisions writes the model as "
                                               "recovered).\n")
                       .arg(decisions)
                       .arg(QDir::toNativeSeparators(run.projectFile()));
        out << QCoreApplication::translate("rosarch::CommandLine",
                                           "Recovered %1 node classes with %2 ports in %3 "
                                           "packages; %4 launch files, %5 launch-file "
                                           "instances, %6 node instances, %7 unresolved items, %8 "
                                           "composites; in %9 ms; %10 diagnostics "
                                           "(%11 errors).\nWrote %12 files to %13\n")
                   .arg(counts.nodes)
                   .arg(counts.ports)
                   .arg(counts.packages)
                   .arg(counts.launchFiles)
                   .arg(counts.launchInstances)
                   .arg(counts.nodeInstances)
                   .arg(counts.unresolved)
                   .arg(counts.composites)
                   .arg(elapsed)
                   .arg(counts.diagnostics)
                   .arg(counts.errors)
                   .arg(written.size())
                   .arg(QDir(parser.value(outOption)).absolutePath());
    }
    out.flush();
    return counts.errors > 0 ? CommandLine::AnalysisErrors : CommandLine::Ok;
}

} // namespace

int CommandLine::parseOrFinish(QCommandLineParser &parser, const QStringList &arguments,
                               const QString &usage)
{
    if (!parser.parse(arguments)) {
        TerminalStream(stderr) << parser.errorText()
                               << (usage.isEmpty() ? QStringLiteral("\n")
                                                   : QStringLiteral("\n\n") + usage);
        return UsageError;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        TerminalStream(stdout) << parser.helpText();
        return Ok;
    }
    return -1;
}

bool CommandLine::isHeadless(int argc, char **argv)
{
    if (argc < 2)
        return false;
    const char *first = argv[1];
    for (const char *cmd : kCommands)
        if (std::strcmp(first, cmd) == 0)
            return true;
    for (const char *opt : {"--help", "-h", "--version", "-v", "--help-all"})
        if (std::strcmp(first, opt) == 0)
            return true;
    // The GUI takes a workspace folder (and Qt's own -options). Anything else is a mistyped
    // command or a wrong path: answered on the terminal, never by opening a window (which,
    // without a display, would abort in Qt's platform plugin).
    return first[0] != '-' && !QFileInfo(QString::fromLocal8Bit(first)).isDir();
}

QString CommandLine::nearestCommand(const QString &written)
{
    // A command within two edits, or one the text starts or is the start of, was meant.
    QString best;
    int bestDistance = 3;
    for (const char *cmd : kCommands) {
        const QString command = QString::fromLatin1(cmd);
        const int d = written.startsWith(command) || command.startsWith(written)
                          ? 1
                          : editDistance(written.toLower(), command, bestDistance + 1);
        if (d < bestDistance) {
            best = command;
            bestDistance = d;
        }
    }
    return best;
}

int CommandLine::run(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    const QString first = arguments.value(1);
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        out << QCoreApplication::applicationName() << ' ' << QCoreApplication::applicationVersion()
            << '\n';
        return Ok;
    }
    if (first == QLatin1String("--help") || first == QLatin1String("-h") ||
        first == QLatin1String("--help-all")) {
        out << usageText();
        return Ok;
    }
    if (first == QLatin1String("recover"))
        return recover(arguments);
    if (first == QLatin1String("check"))
        return runCheck(arguments);
    if (first == QLatin1String("diff"))
        return runDiff(arguments);
    if (first == QLatin1String("eval"))
        return runEval(arguments);
    if (first == QLatin1String("suggest"))
        return runSuggest(arguments);
    if (first == QLatin1String("project"))
        return ProjectCommand::run(arguments);
    if (first == QLatin1String("export"))
        return ExportCommand::run(arguments);
    if (first == QLatin1String("site"))
        return SiteCommand::run(arguments);
    const bool pathLike = first.contains(QLatin1Char('/')) || first.startsWith(QLatin1Char('.')) ||
                          QFileInfo::exists(first);
    if (pathLike) {
        err << QCoreApplication::translate("rosarch::CommandLine",
                                           "Not a folder: %1\nrosarch opens a workspace folder; "
                                           "see rosarch --help.\n")
                   .arg(first);
        return UsageError;
    }
    err << QCoreApplication::translate("rosarch::CommandLine", "Unknown command: %1\n").arg(first);
    if (const QString hint = nearestCommand(first); !hint.isEmpty())
        err << QCoreApplication::translate("rosarch::CommandLine", "Did you mean: rosarch %1?\n")
                   .arg(hint);
    err << '\n' << usageText();
    return UsageError;
}

} // namespace rosarch
