// rosarch-stages: reads StageRequests (model/pipeline/recoverystream.h) on stdin, one after
// the other until stdin ends, runs the stages each asks for and writes frames to stdout:
// progress, the file each thread begins and ends, and the result. The supervisor (StageProcess)
// learns from the frames which file a crash, an exhausted memory budget or an overrun belongs to,
// and starts this again without it.
//
// Exit codes: 0 done, 2 unreadable request, 4 out of memory; a crash ends it by a signal.
//
// For the supervisor's tests only: ROSARCH_STAGES_TEST_CRASH_IN, _HANG_IN and _EXHAUST_IN name
// a substring; the worker crashes, hangs or allocates without bound when it begins a file whose
// path contains it (a stand-in for the analyser bug that nobody has found yet).
#include "cache/analysiscache.h"
#include "core/threadpriority.h"
#include "nodes/nodeanalyzer.h"
#include "pipeline/recovery.h"
#include "pipeline/recoverystream.h"
#include "workspace/workspacescanner.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QIODevice>
#include <QMutex>
#include <QThread>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>
#include <QtEndian>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <new>
#include <optional>
#include <thread>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

namespace {

using namespace rosarch;

QMutex outputMutex;

void writeAll(const QByteArray &bytes)
{
    const char *p = bytes.constData();
    qsizetype left = bytes.size();
    while (left > 0) {
        const ssize_t n = ::write(STDOUT_FILENO, p, size_t(left));
        if (n <= 0)
            _exit(3); // the supervisor went away
        p += n;
        left -= n;
    }
}

/// A payload written already.
struct RawPayload
{
    QByteArray bytes;
};

QDataStream &operator<<(QDataStream &s, const RawPayload &p)
{
    s.writeRawData(p.bytes.constData(), int(p.bytes.size()));
    return s;
}

template <class... T> void frame(stagestream::Frame type, const T &...fields)
{
    QByteArray payload;
    {
        QDataStream out(&payload, QIODevice::WriteOnly);
        out.setVersion(stagestream::kStreamVersion);
        (out << ... << fields);
    }
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(stagestream::kStreamVersion);
    out << quint8(type) << payload;
    QMutexLocker lock(&outputMutex);
    writeAll(bytes);
}

void outOfMemory()
{
    // No unwinding: the files in flight stay in flight for the supervisor to see.
    static const char message[] = "rosarch-stages: out of memory (the memory budget)\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, message, sizeof message - 1);
    _exit(stagestream::kExitOutOfMemory);
}

bool sanitized()
{
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
    return true;
#endif
#endif
    return false;
}

void limitMemory(qint64 budgetMb)
{
    // Sanitizers reserve terabytes of address space for their shadow memory.
    if (budgetMb <= 0 || sanitized())
        return;
    const rlim_t bytes = rlim_t(budgetMb) * 1024 * 1024;
    rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
}

void testFault(const QString &file)
{
    static const QByteArray crash = qgetenv("ROSARCH_STAGES_TEST_CRASH_IN");
    static const QByteArray hang = qgetenv("ROSARCH_STAGES_TEST_HANG_IN");
    static const QByteArray exhaust = qgetenv("ROSARCH_STAGES_TEST_EXHAUST_IN");
    if (!crash.isEmpty() && file.contains(QString::fromUtf8(crash)))
        std::raise(SIGSEGV);
    if (!hang.isEmpty() && file.contains(QString::fromUtf8(hang)))
        for (;;)
            QThread::sleep(1);
    if (!exhaust.isEmpty() && file.contains(QString::fromUtf8(exhaust))) {
        std::vector<std::vector<char>> hog;
        for (;;)
            hog.emplace_back(64 * 1024 * 1024, 'x');
    }
}

/// Reads exactly `size` bytes of stdin; false at its end.
bool readAll(char *into, qsizetype size)
{
    while (size > 0) {
        const ssize_t n = ::read(STDIN_FILENO, into, size_t(size));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        into += n;
        size -= n;
    }
    return true;
}

enum class Read
{
    Request,
    End, ///< the supervisor closed stdin: it is done with this worker, or gone
    Bad,
};

Read readRequest(StageRequest *request)
{
    char header[12];
    if (!readAll(header, sizeof header))
        return Read::End;
    const quint32 magic = qFromBigEndian<quint32>(header);
    const quint32 version = qFromBigEndian<quint32>(header + 4);
    const quint32 length = qFromBigEndian<quint32>(header + 8);
    if (magic != stagestream::kMagic || version != stagestream::kVersion) {
        std::fputs("rosarch-stages: the request is not from this build of rosarch\n", stderr);
        return Read::Bad;
    }
    QByteArray payload(qsizetype(length == 0xffffffffu ? 0 : length), Qt::Uninitialized);
    if (!readAll(payload.data(), payload.size())) {
        std::fputs("rosarch-stages: the request is incomplete\n", stderr);
        return Read::Bad;
    }
    if (!stagestream::decodeRequest(payload, request)) {
        std::fputs("rosarch-stages: the request is incomplete\n", stderr);
        return Read::Bad;
    }
    return Read::Request;
}

/// Whether a progress report goes out: a status bar needs a few a second, not one per file (a
/// frame per file costs the worker and the window a system call and a wake-up each). Messages,
/// a stage's first and last report, and a report 40 ms after the last one sent go out.
bool progressDue(int stage, int done, int total)
{
    static QMutex mutex;
    static QElapsedTimer sent;
    static int lastStage = -1;
    const QMutexLocker lock(&mutex);
    if (total > 0 && done > 0 && done < total && stage == lastStage && sent.isValid() &&
        sent.elapsed() < 40)
        return false;
    lastStage = stage;
    sent.start();
    return true;
}

/// The parts of a reply sent ahead of its Result frame: stage 1's result is encoded and written
/// on a pool thread while stage 2 runs, stage 2's while stage 3 runs, so that the supervisor
/// decodes them meanwhile and only stage 3's part is left when the run is over.
class ReplyAhead
{
public:
    explicit ReplyAhead(const Recovery &base) : m_base(base) {}
    ReplyAhead(const ReplyAhead &) = delete;
    ReplyAhead &operator=(const ReplyAhead &) = delete;
    ~ReplyAhead() { finish(); }

    void send(int stage, const Recovery &sofar)
    {
        const quint8 part = stage == 1 ? stagestream::NodesPart : stagestream::LaunchPart;
        m_sent |= part;
        m_writes.append(QtConcurrent::run([this, part, sofar] {
            QByteArray payload;
            {
                QDataStream out(&payload, QIODevice::WriteOnly);
                out.setVersion(stagestream::kStreamVersion);
                stagestream::writeParts(out, part, sofar, m_base);
            }
            frame(stagestream::Ahead, RawPayload{payload});
        }));
    }
    /// Waits until the parts sent ahead are written; the parts the Result frame has to carry.
    quint8 finish()
    {
        for (QFuture<void> &write : m_writes)
            write.waitForFinished();
        m_writes.clear();
        return quint8(stagestream::AllParts & ~m_sent);
    }

private:
    const Recovery &m_base;
    quint8 m_sent = 0;
    QList<QFuture<void>> m_writes;
};

/// For tests: ROSARCH_STAGES_TEST_CRASH_AFTER_STAGE=N crashes the worker outside any file once
/// stage N's result is sent.
void testStageFault(int stage, ReplyAhead *ahead)
{
    static const int after = qEnvironmentVariableIntValue("ROSARCH_STAGES_TEST_CRASH_AFTER_STAGE");
    if (after > 0 && stage == after) {
        ahead->finish();
        std::fflush(stdout);
        std::raise(SIGSEGV);
    }
}

/// `composed`: the last complete run's stage 3 with its inputs, reused when they are equal.
Recovery run(const StageRequest &request, const Recovery *composed, ReplyAhead *ahead)
{
    StageControl control;
    control.cache = &AnalysisCache::shared();
    control.skipped = request.skipped;
    control.progressed = [](int done, int total, const QString &what) {
        if (progressDue(0, done, total))
            frame(stagestream::Progress, qint32(0), qint32(done), qint32(total), what);
    };
    control.stageProgressed = [](int stage, int done, int total, const QString &what) {
        if (progressDue(stage, done, total))
            frame(stagestream::Progress, qint32(stage), qint32(done), qint32(total), what);
    };
    control.stageTimed = [](int stage, qint64 ms) { frame(stagestream::Timed, qint32(stage), ms); };
    control.fileWork = [](const QString &file, bool entering) {
        const auto thread = quint64(quintptr(QThread::currentThreadId()));
        frame(entering ? stagestream::Enter : stagestream::Leave, thread, file);
        if (entering)
            testFault(file);
    };
    if (request.job == StageRequest::Job::Launch)
        return recoverLaunch(request.root, request.nodes, request.options, control, composed);
    return recoverWorkspace(request.root, request.options, control, composed,
                            [ahead](int stage, const Recovery &sofar) {
                                ahead->send(stage, sofar);
                                testStageFault(stage, ahead);
                            });
}

/// Stage 1's warm-up (NodeAnalyzer::warmUp) while the worker waits for its next request, so
/// that the first edit after a run the stage's memo answered costs what later ones do. The
/// next request stops it at once (stop() before the request runs). Not in a worker of one run
/// (StageRequest::last), which leaves once it has replied and written its cache.
///
/// It starts a moment after the reply: started at once, its pool threads took the cores from
/// the window's UI thread while it showed the reply (the stall benchmark's longest gaps). It
/// runs at the normal priority on the pool, whose threads the next request needs back at once:
/// at the idle priority, a machine busy with other work starved them, and a cancel waited
/// seconds for the warm-up's files to finish.
class IdleWarmUp
{
public:
    ~IdleWarmUp() { stop(); }
    void start(const StageRequest &request)
    {
        stop();
        m_stop = false;
        m_thread = std::thread([this, root = request.root, skipped = request.skipped] {
            {
                std::unique_lock lock(m_mutex);
                if (m_wake.wait_for(lock, kDelay, [this] { return m_stop.load(); }))
                    return; // the next request came first
            }
            // This thread at the lowest priority: it works in what a person's other work leaves
            // of the cores.
            lowerThisThreadPriority(BackgroundPriority::Idle);
            StageControl control; // no progress, no file work: nobody is waiting for it
            control.cache = &AnalysisCache::shared(); // what the next run looks up
            control.canceled = [this] { return m_stop.load(); };
            control.skipped = skipped;
            const Workspace ws = WorkspaceScanner::scan(root, control);
            NodeAnalyzer::warmUp(ws, control);
        });
    }
    void stop()
    {
        {
            const std::lock_guard lock(m_mutex);
            m_stop = true;
        }
        m_wake.notify_all();
        if (m_thread.joinable())
            m_thread.join();
    }

private:
    /// How long the window has to show a reply before the warm-up starts.
    static constexpr std::chrono::milliseconds kDelay{500};

    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::atomic<bool> m_stop{false};
    std::thread m_thread;
};

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    std::set_new_handler(outOfMemory);
    const int threads = QThreadPool::globalInstance()->maxThreadCount();
    bool limited = false;
    // Requests one after the other, until the supervisor closes stdin. Each reply is relative
    // to the previous one (stagestream::writeResult).
    AnalysisCache::shared().setDeferFlush(true);
    Recovery previous;
    std::optional<Recovery> composed; // stage 3 and what it was composed from, for the next run
    IdleWarmUp warmUp;
    const bool warm = qEnvironmentVariableIntValue("ROSARCH_STAGES_NO_WARM_UP") == 0;
    for (;;) {
        StageRequest request;
        const Read read = readRequest(&request);
        warmUp.stop();
        if (read == Read::End)
            return 0;
        if (read == Read::Bad)
            return stagestream::kExitBadRequest;
        if (!limited) // the supervisor sends one budget to a worker
            limitMemory(request.memoryBudgetMb);
        limited = true;
        QThreadPool::globalInstance()->setMaxThreadCount(request.serial ? 1 : threads);
        ReplyAhead ahead(previous);
        Recovery result = run(request, composed ? &*composed : nullptr, &ahead);
        if (!result.launch.canceled && !result.architecture.canceled &&
            (request.job == StageRequest::Job::Launch || !result.nodes.canceled)) {
            composed =
                Recovery{request.job == StageRequest::Job::Launch ? request.nodes : result.nodes,
                         result.launch, result.architecture};
        }
        QByteArray payload;
        {
            QDataStream out(&payload, QIODevice::WriteOnly);
            out.setVersion(stagestream::kStreamVersion);
            stagestream::writeParts(out, ahead.finish(), result, previous);
        }
        frame(stagestream::Result, RawPayload{payload});
        // The cache's pack is written once the supervisor has its reply.
        AnalysisCache::finishStores();
        AnalysisCache::shared().flushDeferred();
        if (warm && !request.last && request.job == StageRequest::Job::Recovery &&
            !result.nodes.canceled)
            warmUp.start(request);
        previous = std::move(result);
    }
}
