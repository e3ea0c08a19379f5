// rosarch-perfbench: how fast recovery is, in one run on one workspace.
//
//   rosarch-perfbench <workspace> [--runs N] [--edit <file>] [--json]
//   rosarch-perfbench --generate packages:N | launch-files:N [--runs N] [--json]
//
// The workspace is copied to a temporary folder first (nothing is written into it). Reported:
// the baseline (a single-core tree-sitter parse of every Python and C++ file the stages
// read), then stages 1-3 through the analysis worker (as the GUI runs them) and in-process:
// without the analysis cache, cold (empty cache), warm (nothing changed) and with one C++
// source file edited; each as a ratio to the baseline, with the peak memory of the process
// that did the analysis. Every recovery runs in a child process of its own, except the
// gui-session rows: one child keeps one StageSession (a long-lived worker) across its runs, as
// the GUI does, so warm and edit runs are measured on a worker that is already running.
// For looking closer at that child (`--session-child <root> <runs> <file> <first edit>`), two
// switches: ROSARCH_PERFBENCH_STAGES=1 prints each stage's time of each run, and
// ROSARCH_PERFBENCH_CHECK=1 compares the last run's result with a fresh one without the cache;
// ROSARCH_PERFBENCH_PAUSE_MS=N waits N ms before each run (a person's pause before an edit).
#include "benchreport.h"
#include "benchsteps.h"
#include "syntheticworkspace.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTextStream>
#include <QThread>

using namespace rosarch::perfbench;

namespace {

struct Plan
{
    QString name;
    Path path;
    bool cache;
    enum Kind
    {
        Cold,
        Warm,
        Edit
    } kind;
    QString target;
    double targetRatio;
    qint64 targetMs;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rosarch-perfbench"));
    const QStringList args = app.arguments();
    if (args.size() == 4 && args.at(1) == QLatin1String("--child"))
        return childMain(args.at(2), args.at(3));
    if (args.size() == 6 && args.at(1) == QLatin1String("--session-child"))
        return sessionChildMain(args.mid(2));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("How fast rosarch recovers a workspace: cold, warm and after editing one "
                       "file, against a single-core tree-sitter parse of the same files."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("workspace"), QStringLiteral("the folder"));
    const QCommandLineOption runsOption(QStringLiteral("runs"),
                                        QStringLiteral("Runs per case (median reported)."),
                                        QStringLiteral("N"), QStringLiteral("3"));
    const QCommandLineOption editOption(
        QStringLiteral("edit"),
        QStringLiteral("The C++ file to edit, relative to the workspace (default: the largest "
                       ".cpp file creating a publisher)."),
        QStringLiteral("file"));
    const QCommandLineOption jsonOption(QStringLiteral("json"),
                                        QStringLiteral("Print the report as JSON."));
    const QCommandLineOption generateOption(
        QStringLiteral("generate"),
        QStringLiteral("Measure a generated workspace instead of a folder: packages:N (N "
                       "packages, as the large-workspace test makes them) or launch-files:N (one "
                       "package with N small launch files)."),
        QStringLiteral("kind:N"));
    parser.addOptions({runsOption, editOption, jsonOption, generateOption});
    parser.process(app);
    QTextStream err(stderr);
    QTextStream out(stdout);
    QTemporaryDir generated;
    QString source;
    if (parser.isSet(generateOption)) {
        const QString kind = parser.value(generateOption).section(QLatin1Char(':'), 0, 0);
        const int count = parser.value(generateOption).section(QLatin1Char(':'), 1).toInt();
        QString error;
        const bool ok =
            count > 0 &&
            (kind == QLatin1String("packages")
                 ? rosarch::SyntheticWorkspace::generate(generated.path(), count, 10, &error)
             : kind == QLatin1String("launch-files")
                 ? rosarch::SyntheticWorkspace::generateLaunchFiles(generated.path(), count, &error)
                 : (error = QStringLiteral("unknown kind"), false));
        if (!ok) {
            err << "--generate packages:N or launch-files:N: " << error << '\n';
            return 2;
        }
        source = generated.path();
    } else if (parser.positionalArguments().size() != 1) {
        err << parser.helpText();
        return 2;
    } else {
        source = QFileInfo(parser.positionalArguments().first()).absoluteFilePath();
    }
    if (!QFileInfo(source).isDir()) {
        err << "Not a folder: " << source << '\n';
        return 2;
    }
    bool ok = false;
    const int runs = parser.value(runsOption).toInt(&ok);
    if (!ok || runs < 1) {
        err << "--runs needs a positive number\n";
        return 2;
    }

    QTemporaryDir temp;
    const QString root = temp.filePath(QStringLiteral("ws"));
    const QString cacheDir = temp.filePath(QStringLiteral("cache"));
    QString error;
    if (!temp.isValid() || !QDir().mkpath(root) || !copyWorkspace(source, root, &error)) {
        err << "rosarch-perfbench: " << (error.isEmpty() ? temp.errorString() : error) << '\n';
        return 3;
    }
    Report report;
    report.workspace = source;
    report.cores = QThread::idealThreadCount();
    const QString edited = pickEditTarget(root, parser.value(editOption));
    if (!edited.isEmpty())
        report.editedFile = QDir(root).relativeFilePath(edited);

    err << "baseline parse...\n";
    QList<qint64> baselineRuns;
    for (int i = 0; i < runs; ++i) {
        report.baseline = parseBaseline(root);
        baselineRuns << report.baseline.ms;
    }
    std::sort(baselineRuns.begin(), baselineRuns.end());
    report.baseline.ms = baselineRuns.at(baselineRuns.size() / 2);

    const QList<Plan> plans = {
        {QStringLiteral("no-cache"), Path::Worker, false, Plan::Cold, {}, 0, 0},
        {QStringLiteral("no-cache"), Path::InProcess, false, Plan::Cold, {}, 0, 0},
        {QStringLiteral("cold"), Path::Worker, true, Plan::Cold, QStringLiteral("<= 1.0x"), 1.0, 0},
        {QStringLiteral("cold"), Path::InProcess, true, Plan::Cold, QStringLiteral("<= 1.0x"), 1.0,
         0},
        {QStringLiteral("warm"), Path::Worker, true, Plan::Warm, QStringLiteral("<= 0.2x"), 0.2, 0},
        {QStringLiteral("warm"), Path::InProcess, true, Plan::Warm, QStringLiteral("<= 0.2x"), 0.2,
         0},
        {QStringLiteral("one-file-edit"), Path::Worker, true, Plan::Edit,
         QStringLiteral("<= 0.1x, < 200 ms"), 0.1, 200},
        {QStringLiteral("one-file-edit"), Path::InProcess, true, Plan::Edit,
         QStringLiteral("<= 0.1x, < 200 ms"), 0.1, 200},
        // The GUI's path: one StageRunner keeps its worker between runs.
        {QStringLiteral("warm"), Path::Session, true, Plan::Warm, QStringLiteral("<= 0.2x"), 0.2,
         0},
        {QStringLiteral("one-file-edit"), Path::Session, true, Plan::Edit,
         QStringLiteral("<= 0.1x, < 200 ms"), 0.1, 200},
        // The command a user runs, end to end: the artifacts written (or kept) included.
        {QStringLiteral("warm"), Path::Command, true, Plan::Warm, QStringLiteral("<= 0.2x"), 0.2,
         0},
    };
    int edits = 0;
    for (const Plan &plan : plans) {
        if (plan.kind == Plan::Edit && edited.isEmpty())
            continue;
        Case c{plan.name, plan.path, {}, 0, plan.target, plan.targetRatio, plan.targetMs};
        err << plan.name
            << (plan.path == Path::Worker      ? " (worker)"
                : plan.path == Path::InProcess ? " (in-process)"
                : plan.path == Path::Command   ? " (recover command)"
                                               : " (gui session)")
            << "...\n";
        if (plan.path == Path::Session) {
            // One child, one worker: an unmeasured first run, then the measured ones.
            const RunResult r =
                runSessionChild(app.applicationFilePath(), root, cacheDir, runs,
                                plan.kind == Plan::Edit ? edited : QString(), edits + 1, &c.ms);
            if (!r.ok) {
                err << "rosarch-perfbench: " << r.error << '\n';
                return 1;
            }
            edits += plan.kind == Plan::Edit ? runs : 0;
            c.peakRssKb = r.peakRssKb;
            report.peakRssKb = std::max(report.peakRssKb, c.peakRssKb);
            report.cases << c;
            continue;
        }
        if (plan.kind != Plan::Cold) // a populated cache to start from
            runChild(app.applicationFilePath(), plan.path, root, cacheDir);
        for (int i = 0; i < runs; ++i) {
            if (plan.kind == Plan::Cold)
                QDir(cacheDir).removeRecursively();
            if (plan.kind == Plan::Edit && !editFile(edited, ++edits)) {
                err << "rosarch-perfbench: cannot edit " << edited << '\n';
                return 3;
            }
            const RunResult r = runChild(app.applicationFilePath(), plan.path, root,
                                         plan.cache ? cacheDir : QString());
            if (!r.ok) {
                err << "rosarch-perfbench: " << r.error << '\n';
                return 1;
            }
            c.ms << r.ms;
            c.peakRssKb = std::max(c.peakRssKb, r.peakRssKb);
        }
        report.peakRssKb = std::max(report.peakRssKb, c.peakRssKb);
        report.cases << c;
    }
    if (parser.isSet(jsonOption))
        out << reportJson(report);
    else
        out << reportText(report);
    return 0;
}
