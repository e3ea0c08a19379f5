#pragma once

#include "launch/launchfileindex.h"

#include <QList>

#include <atomic>
#include <optional>
#include <thread>
#include <vector>

namespace rosarch {

/// Stage 2's reading of the launch files (LaunchFileIndex::read), begun while stage 1 still
/// runs: it needs nothing of stage 1's result. A thread of its own reads the files one after
/// the other next to stage 1's threads, so that stage 1's serial parts (the linkers, the macro
/// index) leave no core idle; take() reads what is left on every pool thread. Its thread runs
/// at the ordinary priority: at a lower one it would hold the analysis cache's lock (and the
/// worker's output lock) while stage 1's threads wait for it. Made only when stage 1 analyses;
/// it reads only on a cold run (the cache off, or its folder without entries: a cache with
/// entries will most likely answer stage 2 by its memo), and never with one analysis thread
/// (the worker's serial mode: one file at a time in flight).
class LaunchReadAhead
{
public:
    LaunchReadAhead(const Workspace &workspace, const StageControl &control);
    /// Whether it reads (else take() gives nothing and stage 2 reads the files itself).
    bool reading() const { return m_thread.joinable(); }
    /// Stops after the file in hand and waits for it.
    ~LaunchReadAhead();
    LaunchReadAhead(const LaunchReadAhead &) = delete;
    LaunchReadAhead &operator=(const LaunchReadAhead &) = delete;

    /// Every candidate read (LaunchFileIndex::candidates' order), what is left read now; none
    /// when nothing was read ahead or the control was canceled. Once only.
    std::optional<QList<LaunchFileRead>> take();

private:
    void readSome();

    const Workspace &m_workspace;
    const StageControl m_control;
    const QList<const SourceFile *> m_files;
    std::vector<LaunchFileRead> m_reads;
    std::atomic<qsizetype> m_next{0};
    std::atomic<bool> m_stop{false};
    std::thread m_thread; ///< not started: nothing is read ahead
};

} // namespace rosarch
