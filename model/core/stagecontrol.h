#pragma once

#include <QString>

#include <functional>

namespace rosarch {

/// Lets a caller watch and cancel a stage without the stage knowing about threads or UI.
struct StageControl
{
    std::function<bool()> canceled; ///< polled between files
    std::function<void(int done, int total, const QString &what)> progressed;

    bool isCanceled() const { return canceled && canceled(); }
    void report(int done, int total, const QString &what) const
    {
        if (progressed)
            progressed(done, total, what);
    }
};

} // namespace rosarch
