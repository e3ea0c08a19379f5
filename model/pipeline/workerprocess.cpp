#include "pipeline/workerprocess.h"

#include <QFile>

#include <mutex>
#include <thread>
#include <vector>

#include <cerrno>
#include <csignal>
#include <cstring>

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

namespace rosarch {

namespace {

/// Blocks SIGPIPE on this thread while alive, and swallows one raised meanwhile: a worker that
/// died between two runs must not take the application with it when the next request is
/// written (QProcess does the same; a process-wide SIG_IGN would change the host's signals).
class NoBrokenPipeSignal
{
public:
    NoBrokenPipeSignal()
    {
        sigemptyset(&m_pipe);
        sigaddset(&m_pipe, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &m_pipe, &m_old);
    }
    ~NoBrokenPipeSignal()
    {
        sigset_t pending;
        sigpending(&pending);
        if (sigismember(&pending, SIGPIPE) == 1) {
            const timespec none{0, 0};
            sigtimedwait(&m_pipe, nullptr, &none);
        }
        pthread_sigmask(SIG_SETMASK, &m_old, nullptr);
    }
    NoBrokenPipeSignal(const NoBrokenPipeSignal &) = delete;
    NoBrokenPipeSignal &operator=(const NoBrokenPipeSignal &) = delete;

private:
    sigset_t m_pipe;
    sigset_t m_old;
};

void closeFd(int *fd)
{
    if (*fd >= 0)
        ::close(*fd);
    *fd = -1;
}

void sleepMs(int ms)
{
    const timespec t{ms / 1000, long(ms % 1000) * 1000000L};
    nanosleep(&t, nullptr);
}

/// The threads that reap released workers; joined when the process exits, so that a released
/// worker's last writes (its cache pack) end before the process does.
class Reapers
{
public:
    ~Reapers() { joinAll(); }
    void joinAll()
    {
        const std::lock_guard lock(m_mutex);
        for (std::thread &t : m_threads)
            t.join();
        m_threads.clear();
    }
    void add(std::thread t)
    {
        const std::lock_guard lock(m_mutex);
        m_threads.push_back(std::move(t));
    }

private:
    std::mutex m_mutex;
    std::vector<std::thread> m_threads;
};

Reapers &reapers()
{
    static Reapers r;
    return r;
}

} // namespace

bool WorkerProcess::start(const QString &program, QString *error)
{
    stop(0);
    m_stdout.clear();
    m_stderr.clear();
    m_exited = m_crashed = false;
    m_exitCode = 0;
    int in[2], out[2], err[2];
    if (pipe2(in, O_CLOEXEC) != 0) {
        *error = QString::fromLocal8Bit(std::strerror(errno));
        return false;
    }
    if (pipe2(out, O_CLOEXEC) != 0 || pipe2(err, O_CLOEXEC) != 0) {
        *error = QString::fromLocal8Bit(std::strerror(errno));
        ::close(in[0]);
        ::close(in[1]);
        return false;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
    const QByteArray path = QFile::encodeName(program);
    char *argv[] = {const_cast<char *>(path.constData()), nullptr};
    pid_t pid = -1;
    const int rc = posix_spawn(&pid, path.constData(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(in[0]);
    ::close(out[1]);
    ::close(err[1]);
    if (rc != 0) {
        *error = QString::fromLocal8Bit(std::strerror(rc));
        ::close(in[1]);
        ::close(out[0]);
        ::close(err[0]);
        return false;
    }
    m_pid = pid;
    m_in = in[1];
    m_out = out[0];
    m_err = err[0];
    fcntl(m_out, F_SETFL, fcntl(m_out, F_GETFL) | O_NONBLOCK);
#ifdef F_SETPIPE_SZ
    // A reply of megabytes in fewer wake-ups of both sides (1 MB: an unprivileged maximum).
    fcntl(m_out, F_SETPIPE_SZ, 1024 * 1024);
#endif
    fcntl(m_err, F_SETFL, fcntl(m_err, F_GETFL) | O_NONBLOCK);
    return true;
}

bool WorkerProcess::write(const QByteArray &bytes)
{
    const NoBrokenPipeSignal quiet;
    const char *p = bytes.constData();
    qsizetype left = bytes.size();
    while (left > 0 && m_in >= 0) {
        const ssize_t n = ::write(m_in, p, size_t(left));
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        p += n;
        left -= n;
    }
    return left == 0;
}

void WorkerProcess::drain(int fd, QByteArray *into)
{
    if (fd < 0)
        return;
    char buffer[64 * 1024];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n > 0) {
            into->append(buffer, n);
            continue;
        }
        if (n < 0 && errno == EINTR)
            continue;
        return; // EAGAIN: nothing more now; 0: the process closed it
    }
}

void WorkerProcess::poll(int ms)
{
    if (m_pid <= 0)
        return;
    pollfd fds[2] = {{m_out, POLLIN, 0}, {m_err, POLLIN, 0}};
    if (!m_exited)
        ::poll(fds, 2, ms);
    drain(m_out, &m_stdout);
    drain(m_err, &m_stderr);
    if (!m_exited && reap(false)) {
        // Whatever it wrote before it ended is in the pipes still.
        drain(m_out, &m_stdout);
        drain(m_err, &m_stderr);
    }
}

bool WorkerProcess::reap(bool wait)
{
    if (m_pid <= 0 || m_exited)
        return m_exited;
    int status = 0;
    pid_t r;
    do {
        r = waitpid(m_pid, &status, wait ? 0 : WNOHANG);
    } while (r < 0 && errno == EINTR);
    if (r != m_pid)
        return false;
    m_exited = true;
    m_crashed = WIFSIGNALED(status);
    m_exitCode = m_crashed ? WTERMSIG(status) : WEXITSTATUS(status);
    return true;
}

void WorkerProcess::kill()
{
    if (m_pid <= 0 || m_exited)
        return;
    ::kill(m_pid, SIGKILL);
    reap(true);
    drain(m_out, &m_stdout);
    drain(m_err, &m_stderr);
}

void WorkerProcess::stop(int graceMs)
{
    if (m_pid > 0 && !m_exited) {
        closeFd(&m_in); // an idle worker leaves on end-of-file
        for (int waited = 0; waited < graceMs && !reap(false); waited += 5)
            sleepMs(5);
        kill();
    }
    closeAll();
    m_pid = -1;
}

void WorkerProcess::release(int graceMs)
{
    if (m_pid <= 0 || m_exited) {
        stop(0);
        return;
    }
    closeFd(&m_in); // an idle worker leaves on end-of-file
    // Its stdout and stderr stay open until it is reaped: a write to a closed pipe would kill
    // it in the middle of its cache write.
    const pid_t pid = m_pid;
    const int out = m_out, err = m_err;
    m_pid = -1;
    m_out = m_err = -1;
    reapers().add(std::thread([pid, out, err, graceMs] {
        WorkerProcess w;
        w.m_pid = pid;
        w.m_out = out;
        w.m_err = err;
        for (int waited = 0; waited < graceMs && !w.reap(false); waited += 5) {
            w.poll(5);
            w.m_stdout.clear();
            w.m_stderr.clear();
        }
        w.stop(0); // kills it if it is still there, and closes the pipes
    }));
}

void WorkerProcess::waitForReleased()
{
    reapers().joinAll();
}

void WorkerProcess::closeAll()
{
    closeFd(&m_in);
    closeFd(&m_out);
    closeFd(&m_err);
}

} // namespace rosarch
