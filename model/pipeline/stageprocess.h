#pragma once

#include "core/atomicnodelist.h"
#include "core/stagecontrol.h"
#include "launch/launchanalyzer.h"
#include "pipeline/recovery.h"

#include <QString>

namespace rosarch {

/// Runs the stages in the analysis worker process, rosarch-stages, and supervises it, so that
/// nothing the analysed code can do to the analysis reaches the caller:
/// - a crash, an exhausted memory budget or a file that overruns its time budget costs that
///   one file: the worker is started again with the file skipped, and the result says so
///   (a `file-skipped` diagnostic naming the file and the reason);
/// - what cannot be pinned on one file ends the run with an error, never the caller;
/// - canceling kills the worker at once.
/// The worker reports which files it is working on (StageControl::fileWork); with two files in
/// flight at a crash it runs once more on one thread to tell which of them it was.
class StageProcess
{
public:
    struct Options
    {
        QString helperPath;             ///< "" = helperPath(): next to the application, ...
        int fileTimeoutMs = 120 * 1000; ///< the time budget of one file's analysis
        qint64 memoryBudgetMb = 4096;   ///< the worker's address space (0 = unlimited)
        int maxAttempts = 6;            ///< worker starts for one run, restarts included
        bool oneShot = false;           ///< one run per worker: it does not warm up for a next one
    };

    struct Result
    {
        Recovery recovery;
        bool canceled = false;
        QString error; ///< why there is no result ("" when there is one)
        int attempts = 0;
        /// A digest of the worker's reply when it alone decides `recovery` (a worker's first
        /// reply, in full): equal digests, equal results. "" otherwise.
        QByteArray replyDigest;
    };

    /// The worker: $ROSARCH_STAGES, else rosarch-stages next to the application, else the one
    /// in the build tree. "" when there is none.
    static QString helperPath(const QString &configured = {});

    /// The warning for a run that had to use the stages in-process, the worker being missing.
    static Diagnostic missingWorker();

    /// Stages 1 to 3 on `root`.
    static Result recover(const QString &root, const LaunchOptions &options,
                          const StageControl &control, const Options &process);
    /// Stages 2 and 3 on `root` against stage 1's `nodes`.
    static Result launch(const QString &root, const AtomicNodeList &nodes,
                         const LaunchOptions &options, const StageControl &control,
                         const Options &process);
};

} // namespace rosarch
