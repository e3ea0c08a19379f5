// rosarch-stallbench: how long the window's UI thread stalls while the stages run on a real
// workspace and while a person types into its filter boxes. Opens the MainWindow offscreen on
// the workspace (as a person opening it), types a text into every filter box key by key and
// erases it again (node list, launch tree, findings, parameters, find in diagram), runs all
// stages once more (F5), then starts runs and cancels them after 300 ms and 1 s. A 10 ms
// timer on the UI thread records every gap; the report names the longest, what ran during
// them (event dispatches and StallScopes), the time until the first result is usable and how
// long a cancel takes until the window says so and until the worker process is gone; last,
// the longest stall while filtering in each panel.
//
//   rosarch-stallbench <workspace> [--runs N] [--no-cancel] [--type-filter TEXT] [--no-filter]
//   rosarch-stallbench --generate <packages> [--runs N] [--no-cancel]
//
// --generate measures a generated workspace of that many packages (the one tst_largeworkspace
// opens with 1,000), written into a temporary folder and removed after.
//
// A benchmark, not a check: it writes nothing into the workspace and exits 0 unless it could
// not run (exit 1) or the run did not finish (exit 2).
#include "app/mainwindow.h"
#include "app/stagerunner.h"
#include "document/document.h"
#include "filterboxes.h"
#include "jobs/stallprobe.h"
#include "stallmonitor.h"
#include "syntheticworkspace.h"
#include "widgets/launchtreepanel.h"

#include <QAction>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QKeyEvent>
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

constexpr int kKeyMs = 150; ///< between two keys typed into a filter box

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
        QStringLiteral("the text typed into every filter box, a key every 150 ms as a person "
                       "looking for something would, then erased key by key (controller)"),
        QStringLiteral("text"), QStringLiteral("controller"));
    const QCommandLineOption noFilter(QStringLiteral("no-filter"),
                                      QStringLiteral("skip typing into the filter boxes"));
    const QCommandLineOption panelOption(
        QStringLiteral("panel"),
        QStringLiteral("type only into this panel's filter box (repeatable): node list, launch "
                       "tree, findings, parameters, diagram find"),
        QStringLiteral("name"));
    parser.addOptions(
        {runsOption, noCancel, top, screenshot, generate, typeFilter, noFilter, panelOption});
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
    StageRunner *runner = w.findChild<StageRunner *>();
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
    if (auto *tree = w.findChild<LaunchTreePanel *>()->findChild<QTreeView *>();
        tree && tree->model()) {
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
    QList<std::pair<QString, qint64>> filterStalls; // panel -> its longest stall
    if (!parser.isSet(noFilter))
        for (const FilterBox &box : filterBoxes(w)) {
            if (parser.isSet(panelOption) && !parser.values(panelOption).contains(box.panel))
                continue;
            app.beginPhase(QStringLiteral("prepare the %1").arg(box.panel));
            box.prepare();
            spinFor(app, 1000);
            const QString text = parser.value(typeFilter);
            const QString phase = QStringLiteral("filter the %1").arg(box.panel);
            app.beginPhase(phase);
            // As keys come: posted events, each dispatched on its own (a key a person types
            // waits for the one before it).
            const auto press = [edit = box.edit](Qt::Key key, const QString &chars) {
                const StallScope scope("a key typed into a filter box");
                QCoreApplication::postEvent(
                    edit, new QKeyEvent(QEvent::KeyPress, key, Qt::NoModifier, chars));
                QCoreApplication::postEvent(
                    edit, new QKeyEvent(QEvent::KeyRelease, key, Qt::NoModifier, chars));
            };
            QElapsedTimer typing;
            typing.start();
            for (int i = 0; i < text.size(); ++i)
                QTimer::singleShot(kKeyMs * i, &app, [&press, c = text.at(i)] {
                    press(Qt::Key(c.toUpper().unicode()), c);
                });
            spinUntil(
                app, [&] { return box.edit->text() == text; }, 60000);
            const qint64 lastKeyShown = typing.elapsed();
            spinFor(app, 1500); // the filter settles (a panel may wait for a pause in typing)
            out() << QStringLiteral("filter the %1: typed \"%2\" a key every %3 ms, the last "
                                    "key shown at %4 ms (typed at %5 ms); %6\n")
                         .arg(box.panel, text)
                         .arg(kKeyMs)
                         .arg(lastKeyShown)
                         .arg(kKeyMs * (text.size() - 1))
                         .arg(box.shown());
            // and erased key by key, down to the whole list again
            for (int i = 0; i < text.size(); ++i)
                QTimer::singleShot(kKeyMs * i, &app,
                                   [&press] { press(Qt::Key_Backspace, QString()); });
            spinUntil(
                app, [&] { return box.edit->text().isEmpty(); }, 60000);
            spinFor(app, 1500);
            out() << QStringLiteral("  erased key by key: %1\n").arg(box.shown());
            reportGaps(app, phase, topGaps);
            filterStalls.append({box.panel, app.longestGap(phase)});
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
    if (!filterStalls.isEmpty()) {
        out() << "longest UI stall while filtering, per panel:\n";
        for (const auto &[panel, ms] : std::as_const(filterStalls))
            out() << QStringLiteral("  %1 %2 ms\n").arg(panel + QLatin1Char(':'), -14).arg(ms);
    }
    out() << QStringLiteral("overall longest UI gap: %1 ms\n").arg(app.longestGap());
    out().flush();
    w.findChild<Document *>()->session()->discardChanges();
    return 0;
}
