// rosarch-stallbench: how long the window's UI thread stalls while the stages run on a real
// workspace. Opens the MainWindow offscreen on the workspace (as a person opening it), runs
// all stages once more (F5), then starts runs and cancels them after 300 ms and 1 s. A 10 ms
// timer on the UI thread records every gap; the report names the longest, what ran during
// them (event dispatches and StallScopes), the time until the first result is usable and how
// long a cancel takes until the window says so and until the worker process is gone.
//
//   rosarch-stallbench <workspace> [--runs N] [--no-cancel] [--type-filter TEXT]
//   rosarch-stallbench --generate <packages> [--runs N] [--no-cancel]
//
// --generate measures a generated workspace of that many packages (the one tst_largeworkspace
// opens with 1,000), written into a temporary folder and removed after.
//
// A benchmark, not a check: it writes nothing into the workspace and exits 0 unless it could
// not run (exit 1) or the run did not finish (exit 2).
#include "document.h"
#include "launchtreepanel.h"
#include "mainwindow.h"
#include "stagerunner.h"
#include "stallmonitor.h"
#include "stallprobe.h"
#include "syntheticworkspace.h"

#include <QAction>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QSet>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTextStream>
#include <QTimer>
#include <QTreeView>

#include <cstdio>

using namespace rosarch;

namespace {

QTextStream &out()
{
    static QTextStream stream(stdout);
    return stream;
}

/// Runs the event loop until `done` or `timeoutMs`; false on timeout.
template <typename Done> bool spinUntil(StallMonitor &, Done done, int timeoutMs)
{
    QElapsedTimer timer;
    timer.start();
    while (!done()) {
        if (timer.elapsed() > timeoutMs)
            return false;
        // sleep in the event loop (processEvents would spin and take a core from the worker)
        QEventLoop loop;
        QTimer::singleShot(5, &loop, &QEventLoop::quit);
        loop.exec();
    }
    return true;
}

void spinFor(StallMonitor &app, int ms)
{
    QElapsedTimer timer;
    timer.start();
    spinUntil(
        app, [&] { return timer.elapsed() >= ms; }, ms + 1000);
}

/// The process ids of the analysis workers this process started that still run.
QSet<QByteArray> runningWorkers()
{
    QSet<QByteArray> out;
    const QDir tasks(QStringLiteral("/proc/self/task"));
    for (const QString &task : tasks.entryList(QDir::Dirs | QDir::NoDotAndDotDot)) {
        QFile children(tasks.filePath(task + QStringLiteral("/children")));
        if (!children.open(QIODevice::ReadOnly))
            continue;
        for (const QByteArray &pid : children.readAll().split(' ')) {
            if (pid.trimmed().isEmpty())
                continue;
            QFile comm(QStringLiteral("/proc/%1/comm").arg(QString::fromLatin1(pid.trimmed())));
            if (comm.open(QIODevice::ReadOnly) && comm.readAll().startsWith("rosarch-stages"))
                out.insert(pid.trimmed());
        }
    }
    return out;
}

QAction *actionWithShortcut(MainWindow &w, const QKeySequence &key)
{
    for (QAction *a : w.findChildren<QAction *>())
        if (a->shortcut() == key)
            return a;
    return nullptr;
}

void reportGaps(const StallMonitor &app, const QString &phase, int top)
{
    const QList<StallMonitor::Gap> gaps = app.gaps(phase);
    out() << QStringLiteral("  longest UI gap: %1 ms (%2 gaps over 50 ms)\n")
                 .arg(app.longestGap(phase))
                 .arg(std::count_if(gaps.begin(), gaps.end(),
                                    [](const StallMonitor::Gap &g) { return g.ms > 50; }));
    for (int i = 0; i < std::min<int>(top, int(gaps.size())); ++i) {
        const StallMonitor::Gap &g = gaps.at(i);
        out() << QStringLiteral("  gap %1 ms ending at %2 s\n")
                     .arg(g.ms)
                     .arg(QString::number(g.endMs / 1000.0, 'f', 2));
        if (!g.during.isEmpty())
            out() << g.during << "\n";
    }
    out().flush();
}

} // namespace

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    StallMonitor app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rosarch-stallbench"));
    QStandardPaths::setTestModeEnabled(true); // no settings or projects of a person's
    QSettings(QStringLiteral("rosarch"), QCoreApplication::applicationName()).clear();

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("How long the window stalls while the stages run on a workspace."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("workspace"), QStringLiteral("a ROS 2 workspace"));
    const QCommandLineOption runsOption(QStringLiteral("runs"),
                                        QStringLiteral("F5 runs after the first open (1)"),
                                        QStringLiteral("n"), QStringLiteral("1"));
    const QCommandLineOption noCancel(QStringLiteral("no-cancel"),
                                      QStringLiteral("skip the cancel measurements"));
    const QCommandLineOption top(QStringLiteral("top"),
                                 QStringLiteral("gaps to detail per phase (3)"),
                                 QStringLiteral("n"), QStringLiteral("3"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"),
                                        QStringLiteral("save the window after the first open"),
                                        QStringLiteral("png"));
    const QCommandLineOption generate(
        QStringLiteral("generate"),
        QStringLiteral("measure a generated workspace of this many packages instead"),
        QStringLiteral("packages"));
    const QCommandLineOption typeFilter(
        QStringLiteral("type-filter"),
        QStringLiteral("type this text into the launch tree's filter, a key every 150 ms, as a "
                       "person looking for a node would"),
        QStringLiteral("text"));
    parser.addOptions({runsOption, noCancel, top, screenshot, generate, typeFilter});
    parser.process(app);
    QTemporaryDir generated;
    QString workspaceArg;
    if (parser.isSet(generate)) {
        bool ok = false;
        const int packages = parser.value(generate).toInt(&ok);
        QString error;
        if (!ok || packages < 1 || packages > 100000 || !generated.isValid()) {
            std::fputs("rosarch-stallbench: --generate takes a number of packages (1-100000)\n",
                       stderr);
            return 1;
        }
        if (!SyntheticWorkspace::generate(generated.path(), packages, 10, &error)) {
            std::fprintf(stderr, "rosarch-stallbench: %s\n", qPrintable(error));
            return 1;
        }
        workspaceArg = generated.path();
        // kept to measure another build on it when asked (as tst_largeworkspace does)
        generated.setAutoRemove(qEnvironmentVariableIsEmpty("ROSARCH_KEEP_LARGE_WORKSPACE"));
        if (!generated.autoRemove())
            std::fprintf(stderr, "workspace kept in %s\n", qPrintable(generated.path()));
    } else if (parser.positionalArguments().size() == 1) {
        workspaceArg = parser.positionalArguments().first();
    }
    if (workspaceArg.isEmpty() || !QFileInfo(workspaceArg).isDir()) {
        std::fputs("rosarch-stallbench: give one workspace folder or --generate (see --help)\n",
                   stderr);
        return 1;
    }
    const QString root = QFileInfo(workspaceArg).canonicalFilePath();
    const int topGaps = parser.value(top).toInt();
    QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation))
             .filePath(QStringLiteral("projects")))
        .removeRecursively();

    MainWindow w;
    w.resize(1400, 900);
    w.show();
    spinFor(app, 300);
    StageRunner *runner = w.runner();
    QAction *cancel = actionWithShortcut(w, QKeySequence(Qt::Key_Escape));
    int finished = 0;
    int canceled = 0;
    qint64 finishedAt = 0;
    qint64 canceledAt = 0;
    QObject::connect(runner, &StageRunner::stageFinished, &app, [&] {
        ++finished;
        finishedAt = app.phaseElapsed();
    });
    QObject::connect(runner, &StageRunner::stageCanceled, &app, [&] {
        ++canceled;
        canceledAt = app.phaseElapsed();
    });
    QStringList statusMessages;
    QObject::connect(w.statusBar(), &QStatusBar::messageChanged, &app, [&](const QString &m) {
        if (!m.isEmpty() && !statusMessages.contains(m))
            statusMessages << m;
    });

    out() << "rosarch-stallbench on " << root << "\n";
    const auto runPhase = [&](const QString &phase, const std::function<void()> &start) {
        app.beginPhase(phase);
        const int before = finished;
        start();
        if (!spinUntil(
                app, [&] { return finished > before; }, 600000)) {
            out() << phase << ": no result within 10 minutes\n";
            return false;
        }
        const qint64 resultAt = finishedAt;
        spinFor(app, 2000); // what the result sets off (layout, views) settles
        const qint64 settled = std::max(resultAt, app.lastGapEnd(50));
        out() << QStringLiteral(
                     "%1: result applied at %2 s, usable (no gap > 50 ms after) at %3 s\n")
                     .arg(phase)
                     .arg(QString::number(resultAt / 1000.0, 'f', 2))
                     .arg(QString::number(settled / 1000.0, 'f', 2));
        reportGaps(app, phase, topGaps);
        return true;
    };

    if (!runPhase(QStringLiteral("open"), [&] { w.openWorkspace(root); }))
        return 2;
    out() << "  status bar said (" << statusMessages.size() << " messages, the last 8):\n";
    for (const QString &m : statusMessages.mid(std::max<qsizetype>(0, statusMessages.size() - 8)))
        out() << "    " << m << "\n";

    // A person clicks the first root launch file: the diagram draws its composite, and the
    // next runs keep that selection.
    if (auto *tree = w.launchPanel()->findChild<QTreeView *>(); tree && tree->model()) {
        app.beginPhase(QStringLiteral("select launch file"));
        // from an event, as a click comes: the report then names what ran in it
        QTimer::singleShot(0, &app, [tree] {
            const StallScope scope("select the launch file (current row changed)");
            tree->setCurrentIndex(tree->model()->index(0, 0));
        });
        spinFor(app, 3000);
        out() << "select launch file " << tree->currentIndex().data().toString() << ":\n";
        reportGaps(app, QStringLiteral("select launch file"), topGaps);
    }
    if (parser.isSet(typeFilter)) {
        QLineEdit *filter = w.launchPanel()->filterEdit();
        const QString text = parser.value(typeFilter);
        app.beginPhase(QStringLiteral("type in the launch filter"));
        QElapsedTimer typing;
        typing.start();
        qint64 lastKeyShown = 0;
        for (int i = 0; i < text.size(); ++i)
            QTimer::singleShot(150 * i, &app, [&, i] {
                const StallScope scope("a key typed into the launch tree's filter");
                filter->insert(text.at(i));
            });
        // until every key has shown and the view has settled
        spinUntil(
            app, [&] { return filter->text() == text; }, 60000);
        lastKeyShown = typing.elapsed();
        spinFor(app, 2000);
        out() << QStringLiteral("type \"%1\" in the launch filter: the last key shown at %2 ms "
                                "(typed at %3 ms); %4 rows shown\n")
                     .arg(text)
                     .arg(lastKeyShown)
                     .arg(150 * (text.size() - 1))
                     .arg(w.launchPanel()->treeView()->model()->rowCount());
        reportGaps(app, QStringLiteral("type in the launch filter"), topGaps);
        filter->clear();
        spinFor(app, 500);
    }
    if (parser.isSet(screenshot))
        w.grab().save(parser.value(screenshot));
    for (int i = 1; i <= parser.value(runsOption).toInt(); ++i)
        if (!runPhase(QStringLiteral("F5 #%1").arg(i), [&] { w.runAllStages(); }))
            return 2;

    if (!parser.isSet(noCancel) && cancel) {
        for (const int after : {300, 1000}) {
            const QString phase = QStringLiteral("cancel after %1 ms").arg(after);
            app.beginPhase(phase);
            const int finishedBefore = finished;
            const int canceledBefore = canceled;
            w.runAllStages();
            spinFor(app, after);
            if (finished > finishedBefore) {
                out() << phase << ": the run finished before the cancel\n";
                continue;
            }
            const qint64 pressed = app.phaseElapsed();
            // The window keeps a worker ahead of need: what has to go is the one that ran.
            const QSet<QByteArray> working = runningWorkers();
            cancel->trigger();
            const bool said = spinUntil(
                app, [&] { return canceled > canceledBefore; }, 60000);
            const qint64 saidAt = said ? canceledAt : -1;
            spinUntil(
                app, [&] { return !runningWorkers().intersects(working); }, 60000);
            const qint64 stoppedAt = app.phaseElapsed();
            out() << QStringLiteral("%1: window said canceled after %2 ms, worker gone after %3 "
                                    "ms%4\n")
                         .arg(phase)
                         .arg(said ? saidAt - pressed : -1)
                         .arg(stoppedAt - pressed)
                         .arg(runner->isRunning() ? QStringLiteral(" (still running!)")
                                                  : QString());
            spinFor(app, 500);
            reportGaps(app, phase, topGaps);
        }
    }
    out() << QStringLiteral("overall longest UI gap: %1 ms\n").arg(app.longestGap());
    out().flush();
    w.document()->discardChanges();
    return 0;
}
