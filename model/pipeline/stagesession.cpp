#include "pipeline/stagesession.h"
#include "cache/sha1.h"
#include "pipeline/recoverystream.h"

#include <QDir>
#include <QElapsedTimer>
#include <QHash>
#include <QtEndian>

#include <chrono>
#include <memory>
#include <thread>

namespace rosarch {

namespace {

QByteArray encode(const StageRequest &r)
{
    const QByteArray payload = stagestream::encodeRequest(r);
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(stagestream::kStreamVersion);
    out << stagestream::kMagic << stagestream::kVersion << payload;
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

} // namespace

/// One request to the worker and what it said.
struct StageSession::Attempt
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
    quint8 parts = 0;     ///< the parts of `recovery` that arrived (stages finished)
    /// Of the result frames, when the reply was relative to no earlier one (else empty).
    std::shared_ptr<Sha1> digest;
};

namespace {

/// Why an attempt ended without a result, for a person; `onFile` when it is said of the file
/// that was being analysed.
template <class A> QString failure(const A &a, const StageProcess::Options &options, bool onFile)
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

} // namespace

StageSession::StageSession(const StageProcess::Options &options, bool startNow)
    : m_options(options), m_helper(StageProcess::helperPath(options.helperPath))
{
    if (startNow) {
        QString ignored; // said by the first run that needs it
        ensureWorker(&ignored);
    }
}

StageSession::~StageSession()
{
    QMutexLocker lock(&m_mutex);
    m_worker.stop();
}

void StageSession::releaseWorker()
{
    QMutexLocker lock(&m_mutex);
    m_worker.release();
    m_base = {};
    m_baseIsEmpty = true;
}

void StageSession::setOptions(const StageProcess::Options &options)
{
    QMutexLocker lock(&m_mutex);
    const QString helper = StageProcess::helperPath(options.helperPath);
    const bool restart = helper != m_helper || options.memoryBudgetMb != m_options.memoryBudgetMb;
    m_options = options;
    m_helper = helper;
    if (restart && m_worker.isRunning()) {
        m_worker.stop();
        QString ignored;
        ensureWorker(&ignored);
    }
}

qint64 StageSession::workerPid()
{
    QMutexLocker lock(&m_mutex);
    return m_worker.isRunning() ? qint64(m_worker.pid()) : -1;
}

int StageSession::workersStarted()
{
    QMutexLocker lock(&m_mutex);
    return m_started;
}

bool StageSession::ensureWorker(QString *error)
{
    if (m_worker.isRunning())
        m_worker.poll(0); // it may have died while idle
    if (m_worker.isRunning())
        return true;
    m_worker.stop(0);
    m_base = {}; // a new worker replies in full
    m_baseIsEmpty = true;
    if (m_helper.isEmpty())
        return false;
    if (!m_worker.start(m_helper, error))
        return false;
    ++m_started;
    return true;
}

StageSession::Attempt StageSession::attempt(const StageRequest &request,
                                            const StageControl &control)
{
    Attempt a;
    QString error;
    if (!ensureWorker(&error)) {
        a.stderrBytes = error.toLocal8Bit();
        a.exitCode = -1;
        return a;
    }
    a.started = true;
    m_worker.output().clear();
    m_worker.errors().clear();
    if (m_baseIsEmpty)
        a.digest = std::make_shared<Sha1>(); // a reply in full: its bytes decide the result
    m_worker.write(encode(request));         // a worker gone already is seen below

    // Per worker thread, the files it is in, innermost last, with when each began.
    QHash<quint64, QList<QPair<QString, qint64>>> flight;
    QElapsedTimer clock;
    clock.start();
    qsizetype read = 0; // frames of output() consumed
    constexpr quint8 kDamaged = 0x80;
    quint8 parts = 0; // of the result, read so far
    auto readFrames = [&] {
        QByteArray &buffer = m_worker.output();
        for (;;) {
            // A frame is its type, a 32-bit big-endian length and the payload.
            if (buffer.size() - read < 5)
                break;
            const quint8 type = quint8(buffer.at(read));
            quint32 length = qFromBigEndian<quint32>(buffer.constData() + read + 1);
            if (length == 0xffffffffu)
                length = 0;
            if (buffer.size() - read < 5 + qint64(length))
                break;
            QDataStream frame(QByteArray::fromRawData(buffer.constData() + read + 5, length));
            frame.setVersion(stagestream::kStreamVersion);
            read += 5 + qsizetype(length);
            if (type == stagestream::Progress) {
                qint32 stage = 0, done = 0, total = 0;
                QString what;
                frame >> stage >> done >> total >> what;
                if (stage > 0 && control.stageProgressed)
                    control.stageProgressed(stage, done, total, what);
                else
                    control.report(done, total, what);
            } else if (type == stagestream::Timed) {
                qint32 stage = 0;
                qint64 ms = 0;
                frame >> stage >> ms;
                if (control.stageTimed)
                    control.stageTimed(stage, ms);
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
            } else if (type == stagestream::Ahead || type == stagestream::Result) {
                if (a.digest)
                    a.digest->addData(QByteArrayView(buffer.constData() + read - length, length));
                // Parts sent ahead are decoded while the worker runs the next stage.
                if (!stagestream::readParts(frame, &a.recovery, m_base, &parts))
                    parts |= kDamaged;
                if (type == stagestream::Result)
                    a.hasResult = parts == stagestream::AllParts;
                if (a.hasResult) {
                    m_base = a.recovery;
                    m_baseIsEmpty = false;
                }
            }
        }
        if (read > 0) {
            buffer.remove(0, read);
            read = 0;
        }
    };
    for (;;) {
        m_worker.poll(25);
        readFrames();
        if (a.hasResult)
            return a; // the worker waits for the next request
        if (parts & kDamaged) {
            // It waits for the next request too, with nothing more to say.
            m_worker.kill();
            a.stderrBytes = m_worker.errors() + "\nits reply could not be read";
            a.exitCode = m_worker.exitCode();
            a.crashed = m_worker.crashed();
            m_worker.stop(0);
            return a;
        }
        QByteArray &errors = m_worker.errors();
        if (errors.size() > 64 * 1024)
            errors = errors.right(16 * 1024);
        if (control.isCanceled()) {
            m_worker.kill();
            m_worker.stop(0);
            QString ignored; // ready for the next run
            ensureWorker(&ignored);
            a.canceled = true;
            return a;
        }
        for (auto it = flight.cbegin(); it != flight.cend() && a.timedOut.isEmpty(); ++it)
            if (!it->isEmpty() &&
                clock.elapsed() - it->constLast().second > m_options.fileTimeoutMs)
                a.timedOut = it->constLast().first;
        if (!a.timedOut.isEmpty()) {
            m_worker.kill();
            a.stderrBytes = m_worker.errors();
            m_worker.stop(0);
            a.inFlight = {a.timedOut};
            return a;
        }
        if (m_worker.exited())
            break;
        // With no frame half read, a moment's pause lets the worker's reports gather (two a
        // file: which files its threads are in), so that this thread wakes a few times in that
        // moment instead of once a frame, each wake-up taken from the worker's threads. A frame
        // half read (a result coming in) is read on at once, so the pipe never holds it up.
        if (m_worker.output().isEmpty())
            std::this_thread::sleep_for(std::chrono::milliseconds(4));
    }
    a.stderrBytes = m_worker.errors();
    a.crashed = m_worker.crashed();
    a.exitCode = m_worker.exitCode();
    a.parts = (parts & kDamaged) ? 0 : parts;
    m_worker.stop(0);
    for (const auto &stack : std::as_const(flight))
        if (!stack.isEmpty())
            a.inFlight.append(stack.constLast().first);
    a.inFlight.sort();
    return a;
}

Recovery StageSession::partial(const Attempt &a, const QString &why)
{
    // What the stages before the stop finished, and an error that says the rest is missing.
    Recovery r = a.recovery;
    const bool launched = a.parts & stagestream::LaunchPart;
    if (!launched)
        r.launch = {};
    r.architecture = {};
    Diagnostic d;
    d.severity = Diagnostic::Severity::Error;
    d.code = QStringLiteral("analysis-incomplete");
    d.message = QStringLiteral("The analysis stopped during stage %1, outside the work on any one "
                               "file (%2); what stage %3 found is kept, stages %1 to 3 have no "
                               "result.")
                    .arg(launched ? 3 : 2)
                    .arg(why)
                    .arg(launched ? QStringLiteral("1 and 2") : QStringLiteral("1"));
    (launched ? r.architecture.diagnostics : r.launch.diagnostics).append(d);
    return r;
}

StageProcess::Result StageSession::supervise(StageRequest request, const StageControl &control)
{
    QMutexLocker lock(&m_mutex);
    StageProcess::Result result;
    if (m_helper.isEmpty()) {
        result.error = QStringLiteral("The analysis worker rosarch-stages was not found next to "
                                      "the application. Set ROSARCH_STAGES to its path.");
        return result;
    }
    request.memoryBudgetMb = m_options.memoryBudgetMb;
    request.last = m_options.oneShot;
    request.skipped = control.skipped;
    while (result.attempts < m_options.maxAttempts) {
        ++result.attempts;
        const Attempt a = attempt(request, control);
        if (a.canceled) {
            result.canceled = true;
            return result;
        }
        if (!a.started) {
            result.error =
                QStringLiteral("The analysis worker %1 could not be started: %2")
                    .arg(QDir::toNativeSeparators(m_helper), QString::fromLocal8Bit(a.stderrBytes));
            return result;
        }
        if (a.hasResult) {
            result.recovery = a.recovery;
            if (a.digest)
                result.replyDigest = a.digest->result();
            return result;
        }
        if (a.inFlight.isEmpty()) {
            if (request.job == StageRequest::Job::Recovery && (a.parts & stagestream::NodesPart)) {
                result.recovery = partial(a, failure(a, m_options, false));
                return result;
            }
            result.error = QStringLiteral("The analysis stopped outside the work on any one file, "
                                          "so there is no result: %1.")
                               .arg(failure(a, m_options, false));
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
        const QString why = failure(a, m_options, true);
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

StageProcess::Result StageSession::recover(const QString &root, const LaunchOptions &options,
                                           const StageControl &control)
{
    StageRequest r;
    r.job = StageRequest::Job::Recovery;
    r.root = root;
    r.options = options;
    return supervise(r, control);
}

StageProcess::Result StageSession::launch(const QString &root, const AtomicNodeList &nodes,
                                          const LaunchOptions &options, const StageControl &control)
{
    StageRequest r;
    r.job = StageRequest::Job::Launch;
    r.root = root;
    r.options = options;
    r.nodes = nodes;
    return supervise(r, control);
}

} // namespace rosarch
