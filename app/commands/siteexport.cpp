#include "app/commands/siteexport.h"

#include <QDir>
#include <QThread>

namespace rosarch {

SiteExport::SiteExport(QObject *parent) : QObject(parent) {}

SiteExport::~SiteExport()
{
    m_cancel = true;
    if (m_thread)
        m_thread->wait();
}

bool SiteExport::isRunning() const
{
    return m_thread && m_thread->isRunning();
}

bool SiteExport::start(const Recovery &recovery, const Project &project, const SiteOptions &options)
{
    if (isRunning())
        return false;
    if (m_thread)
        m_thread->wait();
    m_cancel = false;
    // Signals emitted on the worker reach receivers on this object's thread queued.
    m_thread.reset(QThread::create([this, recovery, project, options] {
        bool canceled = false;
        const QList<SiteFile> files = SiteGenerator::files(
            recovery, project, options,
            [this](int done, int total) {
                emit progressed(done, total);
                return !m_cancel.load();
            },
            &canceled);
        if (canceled) {
            emit finished(false, tr("The site export was canceled; nothing was written."));
            return;
        }
        QString error;
        if (!SiteGenerator::write(files, options.siteFolder, &error)) {
            emit finished(false, error);
            return;
        }
        emit finished(
            true,
            tr("Wrote the architecture site (%1 files) to %2")
                .arg(files.size())
                .arg(QDir::toNativeSeparators(
                    QDir(options.siteFolder).absoluteFilePath(QStringLiteral("index.html")))));
    }));
    m_thread->start();
    return true;
}

} // namespace rosarch
