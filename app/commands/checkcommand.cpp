#include "app/commands/checkcommand.h"
#include "app/commands/commandline.h"
#include "app/commands/terminalstream.h"
#include "app/commands/workspacerun.h"
#include "artifacts/checkreport.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFile>
#include <QSaveFile>
#include <QTextStream>

namespace rosarch {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("rosarch::CheckCommand", text);
}

bool writeAtomically(const QString &path, const QByteArray &data, QString *error)
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit()) {
        *error = tr("Cannot write %1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

} // namespace

int runCheck(const QStringList &arguments)
{
    TerminalStream err(stderr);
    QCommandLineParser parser;
    parser.setApplicationDescription(
        tr("Recover a ROS 2 workspace and report the diagnostics and architecture checks, for "
           "CI.\nExit codes: 0 nothing new at or above --fail-on, 1 new findings at or above "
           "it, 2 usage error, 3 a file could not be read or written."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("check"), QString());
    parser.addPositionalArgument(QStringLiteral("workspace"),
                                 tr("The workspace folder to analyse."));
    const QCommandLineOption formatOption(
        QStringList{QStringLiteral("f"), QStringLiteral("format")},
        tr("text (default), json, sarif or junit."), QStringLiteral("format"),
        QStringLiteral("text"));
    const QCommandLineOption outputOption(
        QStringList{QStringLiteral("o"), QStringLiteral("output")},
        tr("Write the report to this file instead of stdout."), QStringLiteral("file"));
    const QCommandLineOption baselineOption(
        QStringLiteral("baseline"),
        tr("Findings whose keys are in this file (a JSON report of an earlier check, or one key "
           "per line) are reported but never fail; so are those accepted in the project."),
        QStringLiteral("file"));
    const QCommandLineOption writeBaselineOption(
        QStringLiteral("write-baseline"),
        tr("Also write every current finding's key to this file, as a JSON report."),
        QStringLiteral("file"));
    const QCommandLineOption failOnOption(
        QStringLiteral("fail-on"),
        tr("The lowest severity of a new finding that fails: error (default), warning, info, or "
           "never."),
        QStringLiteral("severity"), QStringLiteral("error"));
    for (const QCommandLineOption &o :
         {formatOption, outputOption, baselineOption, writeBaselineOption, failOnOption})
        parser.addOption(o);
    WorkspaceRun run;
    run.addOptions(parser);
    if (const int done = CommandLine::parseOrFinish(parser, arguments); done >= 0)
        return done;

    QString problem;
    const QString format = parser.value(formatOption).toLower();
    const QString failOn = parser.value(failOnOption).toLower();
    const QStringList formats{QStringLiteral("text"), QStringLiteral("json"),
                              QStringLiteral("sarif"), QStringLiteral("junit")};
    const QStringList levels{QStringLiteral("error"), QStringLiteral("warning"),
                             QStringLiteral("info"), QStringLiteral("never")};
    if (!formats.contains(format))
        problem = tr("--format must be text, json, sarif or junit, not '%1'.").arg(format);
    else if (!levels.contains(failOn))
        problem = tr("--fail-on must be error, warning, info or never, not '%1'.").arg(failOn);
    if (!problem.isEmpty() || !run.read(parser, QStringLiteral("check"), &problem)) {
        err << problem << '\n' << tr("See rosarch check --help.") << '\n';
        return CheckUsage;
    }

    QSet<QString> baseline;
    if (parser.isSet(baselineOption)) {
        QFile file(parser.value(baselineOption));
        QString why;
        if (!file.open(QIODevice::ReadOnly)) {
            err << tr("Cannot read the baseline %1: %2\n")
                       .arg(parser.value(baselineOption), file.errorString());
            return CheckIoError;
        }
        if (!CheckReport::readBaseline(file.readAll(), &baseline, &why)) {
            err << tr("The baseline %1 cannot be used: %2\n")
                       .arg(parser.value(baselineOption), why);
            return CheckIoError;
        }
    }

    // Findings a person accepted in the project are known, like those of a baseline.
    for (const FindingMark &mark : run.project().findings)
        if (mark.status == FindingMark::Status::Accepted)
            baseline.insert(mark.key);

    QString failure;
    const Recovery recovery = run.recover(nullptr, &failure);
    if (!failure.isEmpty()) {
        err << failure << '\n';
        return CheckIoError;
    }
    QList<Diagnostic> diagnostics = recovery.nodes.diagnostics;
    diagnostics.append(recovery.launch.diagnostics);
    diagnostics.append(recovery.architecture.diagnostics);
    const Diagnostic::Severity threshold =
        failOn == QLatin1String("warning") ? Diagnostic::Severity::Warning
        : failOn == QLatin1String("info")  ? Diagnostic::Severity::Info
                                           : Diagnostic::Severity::Error;
    const CheckReport report(diagnostics, baseline, threshold, failOn == QLatin1String("never"));
    const QString version = QCoreApplication::applicationVersion();

    QByteArray output;
    if (format == QLatin1String("json"))
        output = report.json(version);
    else if (format == QLatin1String("sarif"))
        output = report.sarif(run.workspace(), version);
    else if (format == QLatin1String("junit"))
        output = report.junit();
    else
        output = report.text().toUtf8();
    QString error;
    if (parser.isSet(outputOption)) {
        if (!writeAtomically(parser.value(outputOption), output, &error)) {
            err << error << '\n';
            return CheckIoError;
        }
    } else {
        QFile out;
        if (!out.open(stdout, QIODevice::WriteOnly) || out.write(output) != output.size()) {
            err << tr("Cannot write the report to the standard output.\n");
            return CheckIoError;
        }
    }
    if (parser.isSet(writeBaselineOption) &&
        !writeAtomically(parser.value(writeBaselineOption), report.json(version), &error)) {
        err << error << '\n';
        return CheckIoError;
    }
    if (format != QLatin1String("text") || parser.isSet(outputOption))
        err << tr("%1 findings; %2 in the baseline; %3 fail the check (--fail-on %4).\n")
                   .arg(report.findings().size())
                   .arg(report.baselined())
                   .arg(report.failing())
                   .arg(failOn);
    return report.failing() > 0 ? CheckFailed : CheckPassed;
}

} // namespace rosarch
