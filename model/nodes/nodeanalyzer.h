#pragma once

#include "core/atomicnodelist.h"
#include "core/stagecontrol.h"
#include "workspace/workspace.h"

#include <functional>

namespace rosarch {

/// Stage 1: runs the Python and C++ analyzers over a scanned workspace and links the node
/// classes to the executables and plugins declared in the build files.
class NodeAnalyzer
{
public:
    /// `analysing` is called when the files are to be analysed (no memo of the whole stage).
    /// `resultKey` (when given) is set to the key the result is a function of: its memo's key
    /// ("" without the cache, or when canceled).
    static AtomicNodeList run(const Workspace &workspace, const StageControl &control = {},
                              const std::function<void()> &analysing = {},
                              QByteArray *resultKey = nullptr);
    /// For an idle long-lived process after a run that stage 1's memo answered: decodes what a
    /// run after an edit reuses (each file's entries, the C++ link, the Python analysis) and
    /// keeps it in the cache's memory (AnalysisCache::recent), so that the first edit costs
    /// what later ones do. Changes no result; stops soon when `control` is canceled.
    static void warmUp(const Workspace &workspace, const StageControl &control);
};

/// Convenience: scan `root` and run stage 1.
AtomicNodeList recoverAtomicNodes(const QString &root, const StageControl &control = {});

} // namespace rosarch
