#pragma once

#include <QByteArray>
#include <QString>

#include <sys/types.h>

namespace rosarch {

/// A child process with pipes on its stdin, stdout and stderr, usable from any thread (a
/// QProcess belongs to the thread that made it, and the stage runs hop between pool threads).
/// Its pipe ends are close-on-exec, so no other child inherits them: when this object goes,
/// the worker reads end-of-file on stdin and exits. Destroying it ends the process and reaps it.
class WorkerProcess
{
public:
    WorkerProcess() = default;
    WorkerProcess(const WorkerProcess &) = delete;
    WorkerProcess &operator=(const WorkerProcess &) = delete;
    ~WorkerProcess() { stop(); }

    /// Starts `program` (no arguments, this process's environment); false with `error` set
    /// when it cannot be started.
    bool start(const QString &program, QString *error);
    bool isRunning() const { return m_pid > 0 && !m_exited; }
    pid_t pid() const { return m_pid; }

    /// Writes all of `bytes` to its stdin; false when it has gone.
    bool write(const QByteArray &bytes);
    /// Waits up to `ms` for output, then appends what there is of stdout and stderr to the
    /// buffers; notices when the process has exited (exited()).
    void poll(int ms);
    QByteArray &output() { return m_stdout; }
    QByteArray &errors() { return m_stderr; }

    /// The process has ended (after poll(), kill() or stop()).
    bool exited() const { return m_exited; }
    /// It ended by a signal; exitCode() is then the signal.
    bool crashed() const { return m_crashed; }
    int exitCode() const { return m_exitCode; }

    /// Kills it at once and reaps it (what it wrote is still in the buffers).
    void kill();
    /// Closes its stdin, gives it `graceMs` to leave, then kills it; forgets it.
    void stop(int graceMs = 300);
    /// stop() without waiting: a thread of its own gives it `graceMs` to leave, kills it then,
    /// and reaps it; this process waits for such threads when it exits. For a worker that has
    /// replied and only writes its cache before it leaves: the grace is long enough for a large
    /// workspace's pack (autoware's cold pack is ~42 MB) on a slow disk, and a worker that leaves
    /// sooner is reaped at once.
    void release(int graceMs = 10000);
    /// Waits until every worker released so far is reaped.
    static void waitForReleased();

private:
    void drain(int fd, QByteArray *into);
    bool reap(bool wait);
    void closeAll();

    pid_t m_pid = -1;
    int m_in = -1, m_out = -1, m_err = -1;
    QByteArray m_stdout, m_stderr;
    bool m_exited = false;
    bool m_crashed = false;
    int m_exitCode = 0;
};

} // namespace rosarch
