#include "launch/launchreadahead.h"

#include "cache/analysiscache.h"
#include "workspace/sourcereader.h"

#include <QDir>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentMap>

namespace rosarch {

LaunchReadAhead::LaunchReadAhead(const Workspace &workspace, const StageControl &control)
    : m_workspace(workspace), m_control(control), m_files(LaunchFileIndex::candidates(workspace)),
      m_reads(size_t(m_files.size()))
{
    AnalysisCache &cache = AnalysisCache::of(m_control);
    // A cache with entries may answer stage 2 by its memo: reading ahead would be work thrown
    // away, and what it decoded would depend on how far it got.
    if (QThreadPool::globalInstance()->maxThreadCount() < 2 ||
        (cache.isEnabled() &&
         !QDir(cache.directory()).entryList({QStringLiteral("*.pack")}, QDir::Files).isEmpty()))
        return;
    // The run of the "launch" entries begins here, not in LaunchAnalyzer::run: what the reading
    // decodes stays for the next run even when the reading outlasts the start of stage 2.
    cache.startRun({QStringLiteral("launch")});
    m_thread = std::thread([this] { readSome(); });
}

LaunchReadAhead::~LaunchReadAhead()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
}

void LaunchReadAhead::readSome()
{
    const SourceReader reader(m_workspace.root);
    AnalysisCache &cache = AnalysisCache::of(m_control);
    for (;;) {
        const qsizetype i = m_next++;
        if (i >= m_files.size() || m_stop || m_control.isCanceled())
            return;
        m_reads[size_t(i)] = LaunchFileIndex::read(*m_files.at(i), reader, m_control, cache);
    }
}

std::optional<QList<LaunchFileRead>> LaunchReadAhead::take()
{
    if (!m_thread.joinable())
        return std::nullopt;
    // What is left, on this thread and the pool's; then the reading thread's file in hand.
    std::vector<int> readers(size_t(QThreadPool::globalInstance()->maxThreadCount()));
    QtConcurrent::blockingMap(readers, [this](int &) { readSome(); });
    m_thread.join();
    m_stop = true;
    if (m_control.isCanceled())
        return std::nullopt;
    return QList<LaunchFileRead>(std::make_move_iterator(m_reads.begin()),
                                 std::make_move_iterator(m_reads.end()));
}

} // namespace rosarch
