#include "app/commands/diffcommand.h"
#include "app/commands/commandline.h"
#include "app/commands/terminalstream.h"
#include "diff/architecturediff.h"
#include "diff/gitrevision.h"
#include "pipeline/recovery.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>
#include <QTemporaryDir>
#include <QTextStream>

namespace rosarch {

namespace {

enum DiffExit
{
    Same = 0,
    Different = 1,
    Usage = 2,
    InputError = 3
};

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::DiffCommand", text);
}

/// An artifact folder is read; any other folder is recovered as a workspace.
bool snapshot(const QString &path, ArchitectureSnapshot *out, QString *error)
{
    if (QFileInfo(QDir(path).filePath(QStringLiteral("atomic_nodes.json"))).isFile())
        return ArchitectureSnapshot::load(path, out, error);
    *out = ArchitectureSnapshot::of(recoverWorkspace(path, {}));
    return true;
}

} // namespace

int runDiff(const QStringList &arguments)
{
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Show what changed between two recoveries: node classes and ports, and per launch "
           "file its parts, topics, services, actions and connections.\nEach side is a folder "
           "`rosarch recover` wrote, or a workspace to recover; --rev A --rev B compares two "
           "git revisions of one workspace.\nExit codes: 0 no change, 1 changes, 2 usage, 3 an "
           "input could not be read."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("diff"), QString());
    parser.addPositionalArgument(
        QStringLiteral("before"),
        tr("Artifact folder or workspace (or, with --rev, the workspace)."));
    parser.addPositionalArgument(QStringLiteral("after"), tr("Artifact folder or workspace."),
                                 QStringLiteral("[after]"));
    const QCommandLineOption revOption(QStringLiteral("rev"),
                                       tr("A git revision of the workspace; give it twice."),
                                       QStringLiteral("revision"));
    const QCommandLineOption formatOption(
        QStringList{QStringLiteral("f"), QStringLiteral("format")}, tr("text (default) or json."),
        QStringLiteral("format"), QStringLiteral("text"));
    const QCommandLineOption outputOption(
        QStringList{QStringLiteral("o"), QStringLiteral("output")},
        tr("Write the report to this file instead of stdout."), QStringLiteral("file"));
    parser.addOption(revOption);
    parser.addOption(formatOption);
    parser.addOption(outputOption);
    if (const int done = CommandLine::parseOrFinish(parser, arguments); done >= 0)
        return done;
    const QStringList positional = parser.positionalArguments();
    const QStringList revs = parser.values(revOption);
    const QString format = parser.value(formatOption).toLower();
    QString problem;
    if (format != QLatin1String("text") && format != QLatin1String("json"))
        problem = tr("--format must be text or json, not '%1'.").arg(format);
    else if (!revs.isEmpty() && (revs.size() != 2 || positional.size() != 2))
        problem = tr("--rev takes one workspace and exactly two revisions: rosarch diff <ws> "
                     "--rev A --rev B.");
    else if (revs.isEmpty() && positional.size() != 3)
        problem = tr("diff needs two folders (artifact folders or workspaces), or one workspace "
                     "and --rev A --rev B.");
    for (qsizetype i = 1; problem.isEmpty() && i < positional.size(); ++i)
        if (!QFileInfo(positional.at(i)).isDir())
            problem = tr("Not a folder: %1").arg(positional.at(i));
    if (!problem.isEmpty()) {
        err << problem << '\n' << tr("See rosarch diff --help.") << '\n';
        return Usage;
    }

    ArchitectureSnapshot before, after;
    QString error;
    if (revs.isEmpty()) {
        if (!snapshot(positional.at(1), &before, &error) ||
            !snapshot(positional.at(2), &after, &error)) {
            err << error << '\n';
            return InputError;
        }
    } else {
        QTemporaryDir a, b;
        if (!a.isValid() || !b.isValid()) {
            err << tr("Cannot create a temporary folder.\n");
            return InputError;
        }
        if (!GitRevision::checkout(positional.at(1), revs.at(0), a.path(), &error) ||
            !GitRevision::checkout(positional.at(1), revs.at(1), b.path(), &error) ||
            !snapshot(a.path(), &before, &error) || !snapshot(b.path(), &after, &error)) {
            err << error << '\n';
            return InputError;
        }
    }
    const QList<ArchitectureChange> changes = ArchitectureDiff::compare(before, after);
    const QByteArray output = format == QLatin1String("json")
                                  ? ArchitectureDiff::json(changes)
                                  : ArchitectureDiff::text(changes).toUtf8();
    if (parser.isSet(outputOption)) {
        QSaveFile file(parser.value(outputOption));
        if (!file.open(QIODevice::WriteOnly) || file.write(output) != output.size() ||
            !file.commit()) {
            err << tr("Cannot write %1: %2\n").arg(parser.value(outputOption), file.errorString());
            return InputError;
        }
    } else {
        QFile out;
        if (!out.open(stdout, QIODevice::WriteOnly) || out.write(output) != output.size())
            return InputError;
    }
    return changes.isEmpty() ? Same : Different;
}

} // namespace rosarch
