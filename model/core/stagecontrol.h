#pragma once

#include "core/diagnostic.h"
#include "core/stagecache.h"

#include <QHash>
#include <QList>
#include <QString>

#include <functional>

namespace rosarch {

/// Lets a caller watch and cancel a stage without the stage knowing about threads or UI.
struct StageControl
{
    std::function<bool()> canceled; ///< polled between files
    std::function<void(int done, int total, const QString &what)> progressed;
    /// Called, from any thread, when the work on one file starts (`entering`) and when it ends.
    /// A supervisor that runs the stages in a worker process learns from it which files were
    /// being analysed when the worker crashed, ran out of memory or overran its time budget.
    std::function<void(const QString &file, bool entering)> fileWork;
    /// Files not to analyse, with the reason: an earlier attempt crashed or ran out of its
    /// budget in them. Each skip becomes a `file-skipped` diagnostic.
    QHash<QString, QString> skipped;
    /// Progress of one stage (1 scan and atomic nodes, 2 launch files, 3 composition): `done`
    /// of `total` files. Unset: progressed gets it.
    std::function<void(int stage, int done, int total, const QString &what)> stageProgressed;
    /// Stage `stage` finished after `ms` milliseconds.
    std::function<void(int stage, qint64 ms)> stageTimed;
    /// Where the stages keep their results for later runs; null: nowhere, every stage computes
    /// everything. The pipeline's entry points give the stages the process's cache when null.
    StageCache *cache = nullptr;

    bool isCanceled() const { return canceled && canceled(); }
    void report(int done, int total, const QString &what) const
    {
        if (progressed)
            progressed(done, total, what);
    }
    /// The control stage `stage` runs with: its progress goes to stageProgressed.
    StageControl forStage(int stage) const;
    /// The control of one part of a stage whose parts report one progression: the part's
    /// `done` is counted after the `before` items of the parts ahead of it, out of `all`.
    StageControl part(int before, int all) const;
};

/// The work on one file, for StageControl::fileWork: construct it before the file is read,
/// and it says so again when it goes out of scope. A file the control says to skip is
/// diagnosed here instead (skip()).
class FileWork
{
public:
    enum class Start
    {
        Now,  ///< the work starts with the object
        Later ///< only at start(): what is found in the cache is no work to say
    };
    FileWork(const StageControl &control, const QString &file, Start start = Start::Now);
    ~FileWork();
    /// Says that the work on the file starts (once; never for a skipped file).
    void start();
    FileWork(const FileWork &) = delete;
    FileWork &operator=(const FileWork &) = delete;

    /// True when the file is not to be analysed; then appends its `file-skipped` diagnostic.
    bool skip(QList<Diagnostic> *diagnostics) const;

private:
    const StageControl &m_control;
    QString m_file;
    bool m_reported = false;
};

} // namespace rosarch
