#pragma once

#include "core/stagecontrol.h"

#include <QString>

#include <atomic>
#include <functional>
#include <memory>

namespace rosarch {

/// What a background job gets from its JobRunner: one cancellation token and a progress and
/// log sink. The job polls the token; the runner delivers progress on the UI thread.
class JobControl
{
public:
    JobControl() = default;

    /// True once the job was canceled or superseded by a newer one.
    bool isCanceled() const { return m_cancel && m_cancel->load(); }
    /// The token itself, for code that polls an atomic (the suggestion engine, the layout).
    const std::atomic_bool *cancelFlag() const { return m_cancel.get(); }
    /// The latest progress: `done` of `total` (0 = unknown) while doing `what`, in `step` of
    /// the job (0 = the job has no steps; the stages: 1 to 3).
    void progress(qint64 done, qint64 total, const QString &what, int step = 0) const
    {
        if (m_progress)
            m_progress(done, total, what, step);
    }
    /// A line for the log, delivered in order.
    void log(const QString &line) const
    {
        if (m_log)
            m_log(line);
    }
    /// The same token and progress in the form the stages take (a stage's number is the
    /// progress step).
    StageControl stageControl() const
    {
        StageControl c;
        c.canceled = [cancel = m_cancel] { return cancel && cancel->load(); };
        c.progressed = [progress = m_progress](int done, int total, const QString &what) {
            if (progress)
                progress(done, total, what, 0);
        };
        c.stageProgressed = [progress = m_progress](int stage, int done, int total,
                                                    const QString &what) {
            if (progress)
                progress(done, total, what, stage);
        };
        return c;
    }

private:
    friend class JobRunner;
    std::shared_ptr<std::atomic_bool> m_cancel;
    std::function<void(qint64, qint64, const QString &, int)> m_progress;
    std::function<void(const QString &)> m_log;
};

} // namespace rosarch
