#include "commandline.h"
#include "artifactwriter.h"
#include "nodeanalyzer.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>

#include <cstring>

namespace rosarch {

namespace {

const char *const kCommands[] = {"recover"};

QString usageText()
{
    return QCoreApplication::translate(
        "rosarch::CommandLine",
        "Usage:\n"
        "  rosarch [workspace]                       open the GUI (on the example workspace by default)\n"
        "  rosarch recover <workspace> --out <dir>   run the stages headless and write the artifacts\n"
        "  rosarch --help | --version\n"
        "\n"
        "Artifacts written by recover: atomic_nodes.json, diagnostics.json, acd/<ClassName>.puml\n"
        "Exit codes: 0 ok, 1 analysis finished with errors reported, 2 usage error.\n");
}

int recover(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate("rosarch::CommandLine",
        "Recover the architecture of a ROS 2 workspace and write the artifacts."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("recover"), QString());
    parser.addPositionalArgument(QStringLiteral("workspace"),
        QCoreApplication::translate("rosarch::CommandLine", "The workspace folder to analyse."));
    const QCommandLineOption outOption(QStringList{QStringLiteral("o"), QStringLiteral("out")},
        QCoreApplication::translate("rosarch::CommandLine", "Folder for the artifacts."),
        QStringLiteral("dir"));
    const QCommandLineOption quietOption(QStringList{QStringLiteral("q"), QStringLiteral("quiet")},
        QCoreApplication::translate("rosarch::CommandLine", "Print only errors."));
    parser.addOption(outOption);
    parser.addOption(quietOption);
    if (!parser.parse(arguments)) {
        err << parser.errorText() << "\n\n" << usageText();
        return CommandLine::UsageError;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << parser.helpText();
        return CommandLine::Ok;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 2 || !parser.isSet(outOption)) {
        err << QCoreApplication::translate("rosarch::CommandLine",
                   "recover needs a workspace folder and --out <dir>.\n\n") << usageText();
        return CommandLine::UsageError;
    }
    const QString workspace = positional.at(1);
    if (!QFileInfo(workspace).isDir()) {
        err << QCoreApplication::translate("rosarch::CommandLine", "Not a folder: %1\n").arg(workspace);
        return CommandLine::UsageError;
    }
    const bool quiet = parser.isSet(quietOption);

    QElapsedTimer timer;
    timer.start();
    const AtomicNodeList nodes = recoverAtomicNodes(workspace);
    const qint64 elapsed = timer.elapsed();

    int errors = 0;
    for (const Diagnostic &d : nodes.diagnostics) {
        if (d.severity == Diagnostic::Severity::Error)
            ++errors;
        if (quiet && d.severity != Diagnostic::Severity::Error)
            continue;
        const QString where = d.evidence.file.isEmpty() ? QString()
                              : d.evidence.line > 0 ? QStringLiteral("%1:%2: ").arg(d.evidence.file).arg(d.evidence.line)
                                                    : d.evidence.file + QStringLiteral(": ");
        err << where << Diagnostic::severityName(d.severity) << ": " << d.message << '\n';
    }
    QStringList written;
    QString error;
    if (!ArtifactWriter::writeAll(nodes, parser.value(outOption), &written, &error)) {
        err << error << '\n';
        return CommandLine::AnalysisErrors;
    }
    if (!quiet) {
        int ports = 0;
        for (const AtomicNode &n : nodes.nodes)
            ports += int(n.ports.size());
        out << QCoreApplication::translate("rosarch::CommandLine",
                   "Recovered %1 node classes with %2 ports in %3 packages in %4 ms; %5 diagnostics (%6 errors).\n"
                   "Wrote %7 files to %8\n")
                   .arg(nodes.nodes.size()).arg(ports).arg(nodes.packages.size()).arg(elapsed)
                   .arg(nodes.diagnostics.size()).arg(errors).arg(written.size())
                   .arg(QDir(parser.value(outOption)).absolutePath());
    }
    out.flush();
    return errors > 0 ? CommandLine::AnalysisErrors : CommandLine::Ok;
}

} // namespace

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
    return false;
}

int CommandLine::run(const QStringList &arguments)
{
    QTextStream out(stdout);
    QTextStream err(stderr);
    const QString first = arguments.value(1);
    if (first == QLatin1String("--version") || first == QLatin1String("-v")) {
        out << QCoreApplication::applicationName() << ' ' << QCoreApplication::applicationVersion() << '\n';
        return Ok;
    }
    if (first == QLatin1String("--help") || first == QLatin1String("-h") || first == QLatin1String("--help-all")) {
        out << usageText();
        return Ok;
    }
    if (first == QLatin1String("recover"))
        return recover(arguments);
    err << QCoreApplication::translate("rosarch::CommandLine", "Unknown command: %1\n\n").arg(first) << usageText();
    return UsageError;
}

} // namespace rosarch
