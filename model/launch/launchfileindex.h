#pragma once

#include "launchaction.h"
#include "stagecontrol.h"
#include "workspace.h"

#include <QStringList>

#include <map>

namespace rosarch {

/// The launch files of a workspace, found by content and each read once (in parallel, through
/// the analysis cache), with the diagnostics of reading them in the files' order.
class LaunchFileIndex
{
public:
    LaunchFileIndex(const Workspace &ws, const StageControl &control,
                    QList<Diagnostic> *diagnostics);

    const LaunchFileDescription *find(const QString &file) const;
    /// Workspace-relative paths, sorted.
    QStringList files() const;

private:
    std::map<QString, LaunchFileDescription> m_files;
};

} // namespace rosarch
