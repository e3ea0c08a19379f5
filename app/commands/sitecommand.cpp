#include "app/commands/sitecommand.h"
#include "app/commands/commandline.h"
#include "app/commands/terminalstream.h"
#include "app/commands/workspacerun.h"
#include "site/sitegenerator.h"
#include "site/sitesource.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::SiteCommand", text);
}

QString usage()
{
    return tr("Usage: rosarch site <workspace> --out <dir> [--title <text>] "
              "[--source-url <pattern>] [--commit <id>] [--no-decisions | --project <file>] "
              "[--in-process] [--no-cache]\n");
}

} // namespace

int SiteCommand::run(const QStringList &arguments)
{
    TerminalStream out(stdout);
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Write the architecture of a ROS 2 workspace as a static HTML site: an index of its "
           "systems, a page per system with its composed diagram, per node class, topic, "
           "service, action, launch file and package, the findings, and a search. No server "
           "and no network are needed to read it."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("site"), QString());
    parser.addPositionalArgument(QStringLiteral("workspace"),
                                 tr("The workspace folder to analyse."));
    const QCommandLineOption outOption(QStringList{QStringLiteral("o"), QStringLiteral("out")},
                                       tr("Folder for the site (empty, new, or a site written "
                                          "before)."),
                                       QStringLiteral("dir"));
    const QCommandLineOption titleOption(
        QStringLiteral("title"), tr("The site's title (default: the workspace folder's name)."),
        QStringLiteral("text"));
    const QCommandLineOption sourceOption(
        QStringLiteral("source-url"),
        tr("Link source lines to hosted source: a pattern with {path} (relative to the "
           "repository root), {line} and {commit}, e.g. "
           "https://github.com/org/repo/blob/{commit}/{path}#L{line}. Default: relative links "
           "to the workspace's files."),
        QStringLiteral("pattern"));
    const QCommandLineOption commitOption(
        QStringLiteral("commit"),
        tr("The commit for {commit} (default: the workspace repository's HEAD)."),
        QStringLiteral("id"));
    for (const QCommandLineOption &o : {outOption, titleOption, sourceOption, commitOption})
        parser.addOption(o);
    WorkspaceRun run;
    run.addOptions(parser);
    if (const int done = CommandLine::parseOrFinish(parser, arguments, usage()); done >= 0)
        return done;
    QString problem;
    if (!parser.isSet(outOption) || parser.value(outOption).isEmpty())
        problem = tr("site needs --out <dir>.");
    const QString pattern = parser.value(sourceOption);
    if (problem.isEmpty() && parser.isSet(sourceOption) &&
        !pattern.contains(QLatin1String("{path}")))
        problem = tr("--source-url needs {path} in its pattern, e.g. "
                     "https://github.com/org/repo/blob/{commit}/{path}#L{line}.");
    if (!problem.isEmpty() || !run.read(parser, QStringLiteral("site"), &problem)) {
        err << problem << "\n\n" << usage();
        return CommandLine::UsageError;
    }

    SiteOptions options;
    options.title = parser.value(titleOption);
    options.workspace = run.workspace();
    options.siteFolder = parser.value(outOption);
    options.version = QCoreApplication::applicationVersion();
    options.sourceUrl = pattern;
    if (!pattern.isEmpty()) {
        QString commit;
        QString prefix;
        const bool inGit = SiteSource::gitInfo(run.workspace(), &commit, &prefix);
        options.repositoryPrefix = prefix;
        options.commit = parser.isSet(commitOption) ? parser.value(commitOption) : commit;
        if (SiteSource::needsCommit(pattern) && options.commit.isEmpty()) {
            err << tr("--source-url has {commit}, but %1 is not in a git repository: give "
                      "--commit <id>.\n")
                       .arg(QDir::toNativeSeparators(run.workspace()));
            return CommandLine::UsageError;
        }
        if (!inGit)
            err << tr("note: %1 is not in a git repository; {path} is relative to it.\n")
                       .arg(QDir::toNativeSeparators(run.workspace()));
    }

    QElapsedTimer clock;
    clock.start();
    QString failure;
    const Recovery recovery = run.recover(nullptr, &failure);
    if (!failure.isEmpty()) {
        err << failure << '\n';
        return CommandLine::AnalysisErrors;
    }
    if (recovery.nodes.packages.isEmpty() && recovery.launch.launchFiles.isEmpty()) {
        err << tr("%1 holds no ROS 2 package (no package.xml) and no launch file: there is "
                  "no architecture to write. Give the workspace folder (the one with src/).\n")
                   .arg(QDir::toNativeSeparators(run.workspace()));
        return CommandLine::AnalysisErrors;
    }
    const qint64 analysed = clock.elapsed();
    const QList<SiteFile> files = SiteGenerator::files(recovery, run.project(), options);
    QString error;
    if (!SiteGenerator::write(files, options.siteFolder, &error)) {
        err << error << '\n';
        return CommandLine::AnalysisErrors;
    }
    qint64 bytes = 0;
    for (const SiteFile &f : files)
        bytes += f.data.size();
    out << tr("Wrote %1 files (%2 KB) to %3 in %4 s (analysis %5 s); open %6.\n")
               .arg(files.size())
               .arg((bytes + 1023) / 1024)
               .arg(QDir::toNativeSeparators(QDir(options.siteFolder).absolutePath()))
               .arg(clock.elapsed() / 1000.0, 0, 'f', 1)
               .arg(analysed / 1000.0, 0, 'f', 1)
               .arg(QDir::toNativeSeparators(
                   QDir(options.siteFolder).absoluteFilePath(QStringLiteral("index.html"))));
    return CommandLine::Ok;
}

} // namespace rosarch
