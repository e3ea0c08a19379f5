#pragma once

#include "pipeline/recovery.h"
#include "project/project.h"
#include "site/sitegenerator.h"

#include <QObject>

#include <atomic>
#include <memory>

class QThread;

namespace rosarch {

/// Writes an architecture site off the calling thread (File > Export Architecture Site): the
/// pages are made and written on a worker, progress and the outcome come back as signals on
/// this object's thread. One export at a time; the destructor cancels and waits.
class SiteExport : public QObject
{
    Q_OBJECT
public:
    explicit SiteExport(QObject *parent = nullptr);
    ~SiteExport() override;

    /// Starts writing the site of `recovery` (the accepted model) to `options.siteFolder`.
    /// False when an export is running already.
    bool start(const Recovery &recovery, const Project &project, const SiteOptions &options);
    /// Stops after the page in progress; finished() then reports the cancellation.
    void cancel() { m_cancel = true; }
    bool isRunning() const;

signals:
    void progressed(int done, int total);
    /// `message` says what was written, or why nothing was, in words for a person.
    void finished(bool ok, const QString &message);

private:
    std::unique_ptr<QThread> m_thread;
    std::atomic_bool m_cancel{false};
};

} // namespace rosarch
