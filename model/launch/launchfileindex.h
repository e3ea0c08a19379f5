#pragma once

#include "core/launchaction.h"
#include "core/stagecontrol.h"
#include "workspace/workspace.h"

#include <QStringList>

#include <map>
#include <optional>

namespace rosarch {

class AnalysisCache;
class SourceReader;

/// One candidate launch file read (LaunchFileIndex::read).
struct LaunchFileRead
{
    bool readable = false;
    QList<Diagnostic> readProblems; ///< already reported by the node analyzers for .py
    std::optional<LaunchFileDescription> description; ///< none when it is no launch file
};

/// The launch files of a workspace, found by content and each read once (in parallel, through
/// the analysis cache), with the diagnostics of reading them in the files' order.
class LaunchFileIndex
{
public:
    LaunchFileIndex(const Workspace &ws, const StageControl &control,
                    QList<Diagnostic> *diagnostics);
    /// The index of files read already: `reads` holds read() of each of candidates(ws), in order.
    LaunchFileIndex(const Workspace &ws, QList<LaunchFileRead> reads, const StageControl &control,
                    QList<Diagnostic> *diagnostics);

    /// The files of `ws` that may be launch files (Python, XML, YAML), in the workspace's order.
    static QList<const SourceFile *> candidates(const Workspace &ws);
    /// Reads one candidate file and, when it is a launch file, its description (through the
    /// cache's "launch" entries). Needs nothing of stage 1: it may run before stage 1 ends.
    static LaunchFileRead read(const SourceFile &file, const SourceReader &reader,
                               const StageControl &control, AnalysisCache &cache);

    const LaunchFileDescription *find(const QString &file) const;
    /// Workspace-relative paths, sorted.
    QStringList files() const;

private:
    std::map<QString, LaunchFileDescription> m_files;
};

} // namespace rosarch
