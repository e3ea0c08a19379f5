#include "pipeline/recovery.h"
#include "cache/analysiscache.h"
#include "cache/evidenceshift.h"
#include "cache/stagememo.h"
#include "compose/composearchitecture.h"
#include "launch/launchreadahead.h"
#include "nodes/nodeanalyzer.h"
#include "pipeline/deferredcachewrite.h"
#include "pipeline/recoverystream.h"
#include "syntax/parsehandoff.h"
#include "workspace/workspacescanner.h"

#include <QElapsedTimer>

namespace rosarch {

RecoveryCounts RecoveryCounts::of(const Recovery &r)
{
    RecoveryCounts c;
    c.packages = r.nodes.packages.size();
    for (const AtomicNode &n : r.nodes.nodes) {
        (n.isPlugin() ? c.plugins : c.nodes) += 1;
        c.ports += n.ports.size();
    }
    c.launchFiles = r.launch.launchFiles.size();
    c.launchInstances = r.launch.instances.size();
    c.nodeInstances = r.launch.nodes.size();
    for (const LaunchFileInstance &i : r.launch.instances)
        c.unresolved += i.unresolved.size();
    for (const NodeInstance &i : r.launch.nodes)
        c.unresolved += i.unresolved.size();
    c.composites = r.architecture.composites.size();
    for (const QList<Diagnostic> *list :
         {&r.nodes.diagnostics, &r.launch.diagnostics, &r.architecture.diagnostics}) {
        c.diagnostics += list->size();
        for (const Diagnostic &d : *list)
            c.errors += d.severity == Diagnostic::Severity::Error ? 1 : 0;
    }
    return c;
}

Architecture composeOrReuse(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                            const StageControl &control, const Recovery *previous)
{
    if (previous && !previous->architecture.canceled && !previous->launch.canceled &&
        !previous->nodes.canceled) {
        // Equal inputs but for locations that moved: the earlier result, with them moved too.
        // Stage 3 reads all of stage 1's result but its diagnostics (Composer,
        // ArchitectureChecks), whose messages may name lines.
        const AtomicNodeList &before = previous->nodes;
        EvidenceShift shift;
        if (before.workspaceRoot == nodes.workspaceRoot &&
            shift.compare(before.packages, nodes.packages) &&
            shift.compare(before.nodes, nodes.nodes) && shift.compare(previous->launch, launch)) {
            shift.compareUnmoved(before.packages, nodes.packages);
            shift.compareUnmoved(before.nodes, nodes.nodes);
            shift.compareUnmoved(previous->launch, launch);
            Architecture reused = previous->architecture;
            if (shift.settle() && shift.apply(reused))
                return reused;
        }
    }
    return composeArchitecture(nodes, launch, control);
}

namespace {

/// `control` with the cache the stages keep their results in: the one it names, else this
/// process's. The entry points choose it, so that the stages use only the cache they are given.
StageControl withCache(const StageControl &control)
{
    StageControl c = control;
    if (!c.cache)
        c.cache = &AnalysisCache::shared();
    return c;
}

} // namespace

Recovery recoverLaunch(const QString &root, const AtomicNodeList &nodes,
                       const LaunchOptions &options, const StageControl &given,
                       const Recovery *previous, const LaunchStage &launchStage)
{
    const StageControl control = withCache(given);
    Recovery r;
    QElapsedTimer clock;
    clock.start();
    const StageControl stage2 = control.forStage(2);
    r.launch = launchStage ? launchStage(root, nodes, options, stage2)
                           : analyzeLaunchFiles(root, nodes, options, stage2);
    if (r.launch.canceled || control.isCanceled())
        return r;
    if (control.stageTimed)
        control.stageTimed(2, clock.restart());
    r.architecture = composeOrReuse(nodes, r.launch, control.forStage(3), previous);
    if (control.stageTimed && !r.architecture.canceled)
        control.stageTimed(3, clock.elapsed());
    return r;
}

namespace {

/// Stage 3's memo in the worker reply's form (stagestream), whose string table makes it a
/// quarter of the size of the cache's own encoding (nav2: ~2 MB instead of ~8 MB).
QByteArray encodeArchitecture(const Architecture &a)
{
    Recovery r;
    r.architecture = a;
    QByteArray bytes;
    QDataStream out(&bytes, QIODevice::WriteOnly);
    out.setVersion(stagestream::kStreamVersion);
    stagestream::writeParts(out, stagestream::ArchitecturePart, r, {});
    return bytes;
}

bool decodeArchitecture(const QByteArray &bytes, Architecture *a)
{
    Recovery r;
    quint8 parts = 0;
    QDataStream in(bytes);
    in.setVersion(stagestream::kStreamVersion);
    if (!stagestream::readParts(in, &r, {}, &parts) || parts != stagestream::ArchitecturePart ||
        !in.atEnd())
        return false;
    *a = std::move(r.architecture);
    return true;
}

/// Stage 3 as composeOrReuse(), or its memo when `key` (made of the keys stages 1 and 2's
/// results are functions of) is not empty, there is no `previous` and the cache has one: a
/// fresh process composes nothing on a run whose stages 1 and 2 came from their memos.
Architecture composeWithMemo(const Recovery &r, const QByteArray &key, const StageControl &control,
                             const Recovery *previous)
{
    if (control.isCanceled()) { // before the memo too: a canceled run does not go on
        Architecture canceled;
        canceled.canceled = true;
        return canceled;
    }
    AnalysisCache &cache = AnalysisCache::of(control);
    // Only in a run without an earlier result: one with it (a long-lived worker's) reuses
    // stage 3 from memory. Its lookups could wait for the pack its last run is writing, and
    // a store would cost an edit run an encoding (nav2's is ~8 MB) and the memory for it,
    // for a memo that only a fresh process reads.
    const bool memo = !key.isEmpty() && !previous && cache.isEnabled();
    if (memo) {
        cache.startRun({QStringLiteral("stage3")});
        if (std::optional<Architecture> a = stagememo::loadWith<Architecture>(
                cache, QStringLiteral("stage3"), key, decodeArchitecture))
            return std::move(*a);
    }
    Architecture a = composeOrReuse(r.nodes, r.launch, control, previous);
    if (memo && !a.canceled) {
        // Encoded on a pool thread when the cache's pack is written later (LaunchAnalyzer).
        cache.storeLater([&cache, key, a] {
            cache.store(QStringLiteral("stage3"), key, encodeArchitecture(a));
        });
        cache.flush();
    }
    return a;
}

} // namespace

Recovery recoverWorkspace(const QString &root, const LaunchOptions &options,
                          const StageControl &given, const Recovery *previous,
                          const StageDone &stageDone)
{
    const StageControl control = withCache(given);
    Recovery r;
    QElapsedTimer clock;
    clock.start();
    const auto timed = [&](int stage) {
        if (control.stageTimed)
            control.stageTimed(stage, clock.restart());
    };
    // The cache's packs are written once the run is over, while the caller goes on with it.
    const DeferredCacheWrite deferred(AnalysisCache::of(control));
    const StageControl stage1 = control.forStage(1);
    // Stages 1 and 2 both read the Python launch files: parsed once, by whichever comes first.
    std::optional<ParseHandoff::Run> handoff;
    handoff.emplace();
    const Workspace ws = WorkspaceScanner::scan(root, stage1);
    const StageControl stage2 = control.forStage(2);
    // Stage 2's reading of the launch files runs in what stage 1 leaves of the cores.
    std::optional<LaunchReadAhead> readAhead;
    QByteArray nodesKey, launchKey; // what stages 1 and 2's results are functions of
    r.nodes = NodeAnalyzer::run(
        ws, stage1, [&] { readAhead.emplace(ws, stage2); }, &nodesKey);
    if (r.nodes.canceled || control.isCanceled()) {
        r.launch.canceled = true;
        return r;
    }
    timed(1);
    if (stageDone)
        stageDone(1, r);
    r.launch = LaunchAnalyzer::run(ws, r.nodes, options, stage2, readAhead ? &*readAhead : nullptr,
                                   &launchKey);
    readAhead.reset();
    handoff.reset(); // what stage 2 did not take
    if (r.launch.canceled || control.isCanceled())
        return r;
    timed(2);
    if (stageDone)
        stageDone(2, r);
    const QByteArray key = nodesKey.isEmpty() || launchKey.isEmpty()
                               ? QByteArray()
                               : AnalysisCache::key({"stage3", nodesKey, launchKey});
    r.architecture = composeWithMemo(r, key, control.forStage(3), previous);
    if (!r.architecture.canceled)
        timed(3);
    return r;
}

} // namespace rosarch
