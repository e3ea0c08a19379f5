#pragma once

#include "launch/launchanalyzer.h"
#include "pipeline/recovery.h"

#include <QDataStream>
#include <QHash>

namespace rosarch {

// Binary streaming of a recovery and what asks for one, for the analysis worker process
// (rosarch-stages) and the application that runs it, in the analysis cache's binary form
// (cachecodec). Every field of every model type is written; round-trip tests compare the
// result with operator== on real fixtures. The format is private to one build of rosarch (the
// worker and the application come from one build), so it carries a version only to catch a
// stale helper.

/// What one start of the analysis worker is asked to do (stdin of rosarch-stages).
struct StageRequest
{
    enum class Job : quint8
    {
        Recovery = 1, ///< stages 1 to 3
        Launch = 2,   ///< stages 2 and 3 against `nodes`
    };
    Job job = Job::Recovery;
    QString root;
    LaunchOptions options;
    AtomicNodeList nodes;            ///< Launch: stage 1's result
    QHash<QString, QString> skipped; ///< files not to analyse, with the reason
    qint64 memoryBudgetMb = 0;       ///< the worker's address space (0 = unlimited)
    bool serial = false;             ///< one analysis thread: one file in flight at a crash
    bool last = false;               ///< no request follows: no warm-up for one
};

namespace stagestream {
/// The first bytes of a request and of every worker reply: "RSTG" and the format version.
constexpr quint32 kMagic = 0x52535447;
constexpr quint32 kVersion = 12;
/// The QDataStream version both sides use.
constexpr QDataStream::Version kStreamVersion = QDataStream::Qt_6_4;
/// The worker's replies on stdout are frames: a type and a payload (QByteArray).
enum Frame : quint8
{
    Progress = 'P', ///< qint32 stage (0 = none), qint32 done, qint32 total, QString what
    Timed = 'T',    ///< qint32 stage, qint64 milliseconds: a stage finished
    Enter = 'E',    ///< quint64 thread, QString file: work on a file begins
    Leave = 'L',    ///< quint64 thread, QString file: and ends
    Ahead = 'S',    ///< parts of the Recovery sent ahead, as soon as their stage is done
    Result = 'R',   ///< the parts not sent ahead; the Recovery is complete (writeParts)
};
/// The parts of a Recovery a reply sends on their own: each stage's result.
enum ResultPart : quint8
{
    NodesPart = 1,
    LaunchPart = 2,
    ArchitecturePart = 4,
    AllParts = 7,
};
/// Writes the `parts` of `v` relative to `base`, the previous result sent on this pipe (the
/// worker's previous reply): a list equal to base's is a flag, and so is each element equal to
/// base's element at the same index (a warm run, or one with a file edited, sends a few
/// elements instead of the whole recovery).
void writeParts(QDataStream &s, quint8 parts, const Recovery &v, const Recovery &base);
/// Reads what writeParts wrote against the same `base` into those parts of `v`, leaving the
/// others, and adds them to `parts`; false when it is damaged.
bool readParts(QDataStream &s, Recovery *v, const Recovery &base, quint8 *parts);
/// All parts of `v` (writeParts).
void writeResult(QDataStream &s, const Recovery &v, const Recovery &base);
/// Reads what writeResult wrote against the same `base`; false when it is damaged or partial.
bool readResult(QDataStream &s, Recovery *v, const Recovery &base);
/// A request as the payload of its frame.
QByteArray encodeRequest(const StageRequest &request);
/// Reads what encodeRequest wrote; false when it is damaged or partial.
bool decodeRequest(const QByteArray &bytes, StageRequest *request);
/// Worker exit codes besides 0 (done) and a signal.
constexpr int kExitBadRequest = 2;
constexpr int kExitOutOfMemory = 4;
} // namespace stagestream

} // namespace rosarch
