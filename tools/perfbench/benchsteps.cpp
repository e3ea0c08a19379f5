#include "benchsteps.h"

#include "cache/analysiscache.h"
#include "pipeline/recovery.h"
#include "pipeline/stageprocess.h"
#include "pipeline/stagesession.h"
#include "pipeline/workerprocess.h"
#include "syntax/syntaxtree.h"
#include "workspace/sourcereader.h"
#include "workspace/workspacescanner.h"

#include <QCoreApplication>
#include <QDirIterator>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTextStream>
#include <QThread>

#include <sys/resource.h>

namespace rosarch::perfbench {

namespace {

qint64 maxRssKb(int who)
{
    rusage usage{};
    getrusage(who, &usage);
    return usage.ru_maxrss; // kilobytes on Linux
}

} // namespace

ParseBaseline parseBaseline(const QString &root)
{
    const Workspace ws = WorkspaceScanner::scan(root);
    const SourceReader reader(ws.root);
    // Read first, so that the figure is parsing alone.
    QList<QPair<SyntaxTree::Grammar, QByteArray>> sources;
    ParseBaseline b;
    for (const SourceFile &f : ws.files) {
        const bool python = f.language == SourceFile::Language::Python;
        if (!python && f.language != SourceFile::Language::Cpp)
            continue;
        QByteArray content;
        QList<Diagnostic> ignored;
        if (!reader.read(f.path, &content, &ignored))
            continue;
        (python ? b.pythonFiles : b.cppFiles) += 1;
        b.bytes += content.size();
        sources.append({python ? SyntaxTree::Grammar::Python : SyntaxTree::Grammar::Cpp, content});
    }
    QElapsedTimer timer;
    timer.start();
    for (const auto &[grammar, content] : std::as_const(sources))
        SyntaxTree::parse(grammar, content, QString());
    b.ms = timer.elapsed();
    return b;
}

namespace {

QProcessEnvironment childEnvironment(const QString &cacheDir)
{
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("ROSARCH_NO_CACHE"));
    env.remove(QStringLiteral("ROSARCH_CACHE_DIR"));
    if (cacheDir.isEmpty())
        env.insert(QStringLiteral("ROSARCH_NO_CACHE"), QStringLiteral("1"));
    else
        env.insert(QStringLiteral("ROSARCH_CACHE_DIR"), cacheDir);
    return env;
}

/// The figures a measuring child printed, once it finished; none, with r->error, if it failed.
QStringList childFigures(QProcess &child, RunResult *r)
{
    if (!child.waitForFinished(30 * 60 * 1000) || child.exitStatus() != QProcess::NormalExit ||
        child.exitCode() != 0) {
        r->error = QString::fromLocal8Bit(child.readAllStandardError()).trimmed();
        if (r->error.isEmpty())
            r->error = QStringLiteral("the measuring child failed (%1)").arg(child.errorString());
        return {};
    }
    return QString::fromLatin1(child.readAllStandardOutput()).simplified().split(QLatin1Char(' '));
}

} // namespace

RunResult runChild(const QString &program, Path path, const QString &root, const QString &cacheDir)
{
    QProcess child;
    child.setProcessEnvironment(childEnvironment(cacheDir));
    child.start(program, {QStringLiteral("--child"),
                          path == Path::Worker    ? QStringLiteral("worker")
                          : path == Path::Command ? QStringLiteral("command")
                                                  : QStringLiteral("inprocess"),
                          root});
    RunResult r;
    const QStringList fields = childFigures(child, &r);
    if (!r.error.isEmpty())
        return r;
    if (fields.size() != 2) {
        r.error = QStringLiteral("the measuring child printed no figures");
        return r;
    }
    r.ms = fields.at(0).toLongLong();
    r.peakRssKb = fields.at(1).toLongLong();
    r.ok = true;
    return r;
}

int childMain(const QString &path, const QString &root)
{
    QElapsedTimer timer;
    timer.start();
    qint64 rss = 0;
    qint64 ms = 0;
    StageControl control;
    if (qEnvironmentVariableIsSet("ROSARCH_PERFBENCH_STAGES")) // where the time goes
        control.stageTimed = [&timer](int stage, qint64 stageMs) {
            QTextStream(stderr) << "stage " << stage << ' ' << stageMs << " ms (at "
                                << timer.elapsed() << " ms)\n";
        };
    if (path == QLatin1String("command")) {
        // The command next to this program, writing beside the copied workspace, as a user
        // runs it again and again into one folder.
        QProcess rosarch;
        rosarch.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        rosarch.setStandardOutputFile(QProcess::nullDevice());
        rosarch.start(QCoreApplication::applicationDirPath() + QStringLiteral("/rosarch"),
                      {QStringLiteral("recover"), root, QStringLiteral("--quiet"),
                       QStringLiteral("--out"), root + QStringLiteral("-artifacts")});
        if (!rosarch.waitForFinished(30 * 60 * 1000) || rosarch.exitCode() > 1) {
            QTextStream(stderr) << "rosarch-perfbench: rosarch recover failed\n";
            return 1;
        }
        ms = timer.elapsed();
        rss = maxRssKb(RUSAGE_CHILDREN); // the command or its worker, whichever was larger
    } else if (path == QLatin1String("worker")) {
        const StageProcess::Result r = StageProcess::recover(root, {}, control, {});
        ms = timer.elapsed(); // the worker writes its cache after that, on its own
        if (!r.error.isEmpty()) {
            QTextStream(stderr) << "rosarch-perfbench: the worker failed: " << r.error << '\n';
            return 1;
        }
        WorkerProcess::waitForReleased();
        rss = maxRssKb(RUSAGE_CHILDREN); // the worker, which did the analysis
    } else {
        const Recovery r = recoverWorkspace(root, {}, control);
        ms = timer.elapsed();
        rss = maxRssKb(RUSAGE_SELF);
    }
    QTextStream(stdout) << ms << ' ' << rss << '\n';
    return 0;
}

RunResult runSessionChild(const QString &program, const QString &root, const QString &cacheDir,
                          int runs, const QString &editedFile, int firstEdit, QList<qint64> *ms)
{
    QProcess child;
    child.setProcessEnvironment(childEnvironment(cacheDir));
    child.start(program, {QStringLiteral("--session-child"), root, QString::number(runs),
                          editedFile, QString::number(firstEdit)});
    RunResult r;
    const QStringList fields = childFigures(child, &r);
    if (!r.error.isEmpty())
        return r;
    if (fields.size() != runs + 1) {
        r.error = QStringLiteral("the measuring child printed no figures");
        return r;
    }
    r.peakRssKb = fields.at(0).toLongLong();
    for (int i = 1; i < fields.size(); ++i)
        ms->append(fields.at(i).toLongLong());
    r.ok = true;
    return r;
}

int sessionChildMain(const QStringList &args)
{
    // args: root, runs, edited file ("" none), first edit number
    const QString root = args.value(0);
    const int runs = args.value(1).toInt();
    const QString edited = args.value(2);
    int edit = args.value(3).toInt();
    QList<qint64> times;
    {
        StageSession session;
        StageProcess::Result first = session.recover(root, {}, {});
        if (!first.error.isEmpty()) {
            QTextStream(stderr) << "rosarch-perfbench: the worker failed: " << first.error << '\n';
            return 1;
        }
        // A person's pause before each edit (ms), in which the idle worker warms up.
        const int pause = qEnvironmentVariableIntValue("ROSARCH_PERFBENCH_PAUSE_MS");
        for (int i = 0; i < runs; ++i) {
            if (pause > 0)
                QThread::msleep(ulong(pause));
            if (!edited.isEmpty() && !editFile(edited, edit++)) {
                QTextStream(stderr) << "rosarch-perfbench: cannot edit " << edited << '\n';
                return 1;
            }
            QElapsedTimer timer;
            timer.start();
            StageControl control;
            if (qEnvironmentVariableIsSet("ROSARCH_PERFBENCH_STAGES")) // where a run's time goes
                control.stageTimed = [&timer](int stage, qint64 ms) {
                    QTextStream(stderr) << "stage " << stage << ' ' << ms << " ms (at "
                                        << timer.elapsed() << " ms)\n";
                };
            const StageProcess::Result r = session.recover(root, {}, control);
            times << timer.elapsed();
            if (!r.error.isEmpty()) {
                QTextStream(stderr) << "rosarch-perfbench: the worker failed: " << r.error << '\n';
                return 1;
            }
            if (i == runs - 1 && qEnvironmentVariableIsSet("ROSARCH_PERFBENCH_CHECK")) {
                // The session's last result against a fresh run without the cache.
                AnalysisCache off{QString()};
                StageControl fresh;
                fresh.cache = &off;
                const Recovery expected = recoverWorkspace(root, {}, fresh);
                QTextStream(stderr)
                    << "check: stage 1 "
                    << (expected.nodes == r.recovery.nodes ? "same" : "DIFFERENT") << ", stage 2 "
                    << (expected.launch == r.recovery.launch ? "same" : "DIFFERENT") << ", stage 3 "
                    << (expected.architecture == r.recovery.architecture ? "same" : "DIFFERENT")
                    << '\n';
                if (!(expected == r.recovery))
                    return 1;
            }
        }
    } // the worker is reaped here, so that its peak memory is counted
    QTextStream out(stdout);
    out << maxRssKb(RUSAGE_CHILDREN);
    for (qint64 ms : std::as_const(times))
        out << ' ' << ms;
    out << '\n';
    return 0;
}

bool copyWorkspace(const QString &from, const QString &to, QString *error)
{
    QProcess cp;
    cp.start(QStringLiteral("cp"), {QStringLiteral("-a"), from + QStringLiteral("/."), to});
    if (!cp.waitForFinished(10 * 60 * 1000) || cp.exitCode() != 0) {
        *error = QStringLiteral("copying %1 failed: %2")
                     .arg(from, QString::fromLocal8Bit(cp.readAllStandardError()).trimmed());
        return false;
    }
    return true;
}

QString pickEditTarget(const QString &root, const QString &wanted)
{
    if (!wanted.isEmpty())
        return QFileInfo(QDir(root), wanted).absoluteFilePath();
    QString best;
    qint64 bestSize = -1;
    const Workspace ws = WorkspaceScanner::scan(root);
    for (const SourceFile &f : ws.files) {
        if (f.language != SourceFile::Language::Cpp || !f.path.endsWith(QLatin1String(".cpp")) ||
            f.size <= bestSize)
            continue;
        QFile file(ws.absolutePath(f.path));
        if (file.open(QIODevice::ReadOnly) && file.readAll().contains("create_publisher")) {
            best = ws.absolutePath(f.path);
            bestSize = f.size;
        }
    }
    return best;
}

bool editFile(const QString &file, int n)
{
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return false;
    QByteArray content = f.readAll();
    f.close();
    if (content.startsWith("// rosarch-perfbench edit"))
        content.remove(0, content.indexOf('\n') + 1);
    content.prepend("// rosarch-perfbench edit " + QByteArray::number(n) + '\n');
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
        return false;
    return f.write(content) == content.size();
}

} // namespace rosarch::perfbench
