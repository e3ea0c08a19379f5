#pragma once

#include "core/atomicnodelist.h"
#include "pipeline/recovery.h"

#include <QString>
#include <QStringList>

namespace rosarch {

/// Writes a run's artifacts into one folder with the fixed layout:
/// atomic_nodes.json, launch_dependencies.json, architecture.json, diagnostics.json,
/// acd/<ClassName>.puml, ccd/<launch stem>.puml, mermaid/<launch stem>.md (the CCD as a
/// Mermaid flowchart) and graph/<root launch stem>.dot (a root system's communication graph).
/// Earlier diagrams (and their rendered pictures) in those folders are removed; other files of
/// the folder stay. The folder is replaced as ArtifactCommit describes: a failed or killed run
/// (a full disk, a kill) leaves the previous artifacts intact, never a mix of old and new.
class ArtifactWriter
{
public:
    /// Returns false with a message when a file cannot be written; `written` lists the files.
    /// `madeFrom`, when given, is a digest of what decided `recovery` (WorkspaceRun::recover):
    /// the artifacts' stamp is then made from it, not from the recovery (which costs a tenth of
    /// a warm run on navigation2).
    /// `notice`, when given, receives what the person should know of a write that succeeded:
    /// that the folder could not be replaced in one step, and why ("" when it was).
    static bool writeAll(const Recovery &recovery, const QString &dir, QStringList *written,
                         QString *error, const QByteArray &madeFrom = {},
                         QString *notice = nullptr);
    /// Stage 1 only (no launch_dependencies.json).
    static bool writeAll(const AtomicNodeList &nodes, const QString &dir, QStringList *written,
                         QString *error);

private:
    static bool writeAll(const Recovery &recovery, const QString &dir, QStringList *written,
                         QString *error, bool withLaunch, const QByteArray &madeFrom,
                         QString *notice);
};

} // namespace rosarch
