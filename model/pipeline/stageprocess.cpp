#include "stageprocess.h"
#include "helperprogram.h"
#include "recoverystream.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QHash>
#include <QProcess>
#include <QtEndian>

namespace rosarch {

namespace {

using Request = StageRequest;
using Job = StageRequest::Job;

QByteArray encode(const Request &r)
{
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(stagestream::kStreamVersion);
    out << stagestream::kMagic << stagestream::kVersion << r;
    return bytes;
}

QString seconds(int ms)
{
    return QString::number(ms / 1000.0, 'g', 3);
}

/// The last lines a worker wrote to stderr, for a message.
QString tail(const QByteArray &stderrBytes)
{
    QString text = QString::fromLocal8Bit(stderrBytes).trimmed();
    QStringList lines = text.split(QLatin1Char('\n'));
    if (lines.size() > 4)
        lines = lines.mid(lines.size() - 4);
    text = lines.join(QLatin1String(" / "));
    for (QChar &c : text)
        if (c.category() == QChar::Other_Control)
            c = QLatin1Char('?');
    return text.left(600);
}

/// One start of the worker and what it said.
struct Attempt
{
    bool started = false;
    bool canceled = false;
    bool hasResult = false;
    Recovery recovery;
    bool crashed = false;
    int exitCode = 0;
    QByteArray stderrBytes;
    QString timedOut;     ///< the file that overran its time budget (the worker was killed)
    QStringList inFlight; ///< files being analysed when the worker stopped
};

class Supervisor
{
public:
    Supervisor(const QString &helper, const StageControl &control,
               const StageProcess::Options &options)
        : m_helper(helper), m_control(control), m_options(options)
    {
    }

    Attempt run(const Request &request)
    {
        Attempt a;
        QProcess process;
        process.setProgram(m_helper);
        process.start();
        if (!process.waitForStarted(10000)) {
            a.stderrBytes = process.errorString().toLocal8Bit();
            a.exitCode = -1;
            return a;
        }
        a.started = true;
        process.write(encode(request));
        process.closeWriteChannel();

        QDataStream in(&process);
        in.setVersion(stagestream::kStreamVersion);
        // Per worker thread, the files it is in, innermost last, with when each began.
        QHash<quint64, QList<QPair<QString, qint64>>> flight;
        QElapsedTimer clock;
        clock.start();
        auto readFrames = [&] {
            for (;;) {
                // A frame is its type, a 32-bit big-endian length and the payload: wait for
                // all of it before reading (reading a large result as it trickles in through
                // the pipe would copy it again for every chunk).
                const QByteArray header = process.peek(5);
                if (header.size() < 5)
                    return;
                const quint32 length = qFromBigEndian<quint32>(header.constData() + 1);
                if (process.bytesAvailable() < 5 + qint64(length))
                    return;
                quint8 type = 0;
                QByteArray payload;
                in >> type >> payload;
                QDataStream frame(payload);
                frame.setVersion(stagestream::kStreamVersion);
                if (type == stagestream::Progress) {
                    qint32 stage = 0, done = 0, total = 0;
                    QString what;
                    frame >> stage >> done >> total >> what;
                    if (stage > 0 && m_control.stageProgressed)
                        m_control.stageProgressed(stage, done, total, what);
                    else
                        m_control.report(done, total, what);
                } else if (type == stagestream::Timed) {
                    qint32 stage = 0;
                    qint64 ms = 0;
                    frame >> stage >> ms;
                    if (m_control.stageTimed)
                        m_control.stageTimed(stage, ms);
                } else if (type == stagestream::Enter || type == stagestream::Leave) {
                    quint64 thread = 0;
                    QString file;
                    frame >> thread >> file;
                    auto &stack = flight[thread];
                    if (type == stagestream::Enter) {
                        stack.append({file, clock.elapsed()});
                    } else {
                        for (qsizetype i = stack.size() - 1; i >= 0; --i)
                            if (stack.at(i).first == file) {
                                stack.remove(i);
                                break;
                            }
                    }
                } else if (type == stagestream::Result) {
                    frame >> a.recovery;
                    a.hasResult = frame.status() == QDataStream::Ok;
                }
            }
        };
        for (;;) {
            process.waitForReadyRead(25);
            readFrames();
            a.stderrBytes += process.readAllStandardError();
            if (a.stderrBytes.size() > 64 * 1024)
                a.stderrBytes = a.stderrBytes.right(16 * 1024);
            if (m_control.isCanceled()) {
                process.kill();
                process.waitForFinished(5000);
                a.canceled = true;
                return a;
            }
            for (auto it = flight.cbegin(); it != flight.cend() && a.timedOut.isEmpty(); ++it)
                if (!it->isEmpty() &&
                    clock.elapsed() - it->constLast().second > m_options.fileTimeoutMs)
                    a.timedOut = it->constLast().first;
            if (!a.timedOut.isEmpty()) {
                process.kill();
                process.waitForFinished(5000);
                a.inFlight = {a.timedOut};
                return a;
            }
            if (process.state() == QProcess::NotRunning) {
                readFrames();
                a.stderrBytes += process.readAllStandardError();
                break;
            }
        }
        a.crashed = process.exitStatus() == QProcess::CrashExit;
        a.exitCode = process.exitCode();
        for (const auto &stack : std::as_const(flight))
            if (!stack.isEmpty())
                a.inFlight.append(stack.constLast().first);
        a.inFlight.sort();
        return a;
    }

private:
    QString m_helper;
    const StageControl &m_control;
    StageProcess::Options m_options;
};

/// Why an attempt ended without a result, for a person; `onFile` when it is said of the file
/// that was being analysed.
QString failure(const Attempt &a, const StageProcess::Options &options, bool onFile)
{
    if (!a.timedOut.isEmpty())
        return QStringLiteral("its analysis took longer than the time budget of %1 s per file")
            .arg(seconds(options.fileTimeoutMs));
    const QString detail = tail(a.stderrBytes);
    QString why;
    if (a.exitCode == stagestream::kExitOutOfMemory ||
        detail.contains(QLatin1String("failed to allocate")))
        why = QStringLiteral("the analysis worker exhausted its memory budget of %1 MB")
                  .arg(options.memoryBudgetMb);
    else if (a.crashed)
        why = QStringLiteral("the analysis worker crashed (signal %1)").arg(a.exitCode);
    else
        why = QStringLiteral("the analysis worker stopped (exit code %1)").arg(a.exitCode);
    if (onFile)
        why += QStringLiteral(" on it");
    if (!detail.isEmpty())
        why += QStringLiteral(": ") + detail;
    return why;
}

StageProcess::Result supervise(Request request, const StageControl &control,
                               const StageProcess::Options &options)
{
    StageProcess::Result result;
    const QString helper = StageProcess::helperPath(options.helperPath);
    if (helper.isEmpty()) {
        result.error = QStringLiteral("The analysis worker rosarch-stages was not found next to "
                                      "the application. Set ROSARCH_STAGES to its path.");
        return result;
    }
    request.memoryBudgetMb = options.memoryBudgetMb;
    request.skipped = control.skipped;
    Supervisor supervisor(helper, control, options);
    while (result.attempts < options.maxAttempts) {
        ++result.attempts;
        const Attempt a = supervisor.run(request);
        if (a.canceled) {
            result.canceled = true;
            return result;
        }
        if (!a.started) {
            result.error =
                QStringLiteral("The analysis worker %1 could not be started: %2")
                    .arg(QDir::toNativeSeparators(helper), QString::fromLocal8Bit(a.stderrBytes));
            return result;
        }
        if (a.hasResult && !a.crashed && a.exitCode == 0) {
            result.recovery = a.recovery;
            return result;
        }
        if (a.inFlight.isEmpty()) {
            result.error = QStringLiteral("The analysis stopped outside the work on any one file, "
                                          "so there is no result: %1.")
                               .arg(failure(a, options, false));
            return result;
        }
        if (a.inFlight.size() > 1 && !request.serial) {
            // Two files in flight: once more on one thread tells which of them it was.
            request.serial = true;
            control.report(0, 0,
                           QStringLiteral("Repeating the analysis on one thread to find the file "
                                          "it stopped on…"));
            continue;
        }
        const QString why = failure(a, options, true);
        for (const QString &file : a.inFlight)
            request.skipped.insert(file, why);
        request.serial = false;
        control.report(0, 0,
                       QStringLiteral("Repeating the analysis without %1…")
                           .arg(a.inFlight.join(QLatin1String(", "))));
    }
    result.error = QStringLiteral("The analysis stopped %1 times; giving up.").arg(result.attempts);
    return result;
}

} // namespace

QString StageProcess::helperPath(const QString &configured)
{
#ifdef ROSARCH_STAGES_HELPER
    const QString buildTree = QStringLiteral(ROSARCH_STAGES_HELPER);
#else
    const QString buildTree;
#endif
    return findHelperProgram(configured, "ROSARCH_STAGES", QStringLiteral("rosarch-stages"),
                             buildTree);
}

Diagnostic StageProcess::missingWorker()
{
    Diagnostic d;
    d.severity = Diagnostic::Severity::Warning;
    d.code = QStringLiteral("worker-missing");
    d.message = QStringLiteral("The analysis worker rosarch-stages was not found next to the "
                               "application, so the stages ran without crash isolation and "
                               "without per-file budgets.");
    return d;
}

StageProcess::Result StageProcess::recover(const QString &root, const LaunchOptions &options,
                                           const StageControl &control, const Options &process)
{
    Request r;
    r.job = Job::Recovery;
    r.root = root;
    r.options = options;
    return supervise(r, control, process);
}

StageProcess::Result StageProcess::launch(const QString &root, const AtomicNodeList &nodes,
                                          const LaunchOptions &options, const StageControl &control,
                                          const Options &process)
{
    Request r;
    r.job = Job::Launch;
    r.root = root;
    r.options = options;
    r.nodes = nodes;
    return supervise(r, control, process);
}

} // namespace rosarch
