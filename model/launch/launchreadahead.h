#pragma once

#include "launchfileindex.h"

#include <QList>

#include <atomic>
#include <optional>
#include <thread>
#include <vector>

namespace rosarch {

/// Stage 2's reading of the launch files (LaunchFileIndex::read), begun while stage 1 still
/// runs: it needs nothing of stage 1's result. A thread of its own, at the lowest scheduling
/// priority, reads the files one after the other, so that it takes only the time stage 1 leaves
/// a core idle (its serial parts); take() reads what is left on every pool thread. Started
/// only when stage 1 analyses (a stage-1 memo hit means a stage-2 memo hit, most likely), and
/// never with one analysis thread (the worker's serial mode: one file at a time in flight).
class LaunchReadAhead
{
public:
    LaunchReadAhead(const Workspace &workspace, const StageControl &control);
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
