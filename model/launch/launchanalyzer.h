#pragma once

#include <functional>

#include "core/atomicnodelist.h"
#include "core/launchaction.h"
#include "core/launchdependencies.h"
#include "core/stagecontrol.h"
#include "workspace/workspace.h"

#include <QMap>
#include <QString>

#include <optional>

namespace rosarch {

class LaunchReadAhead;

/// What a person chose for stage 2: the root launch file and launch argument values.
/// What a person chose for the analysis (kept in the project): the launch root and argument
/// values stage 2 runs with, and the ports expected to meet something outside the workspace.
struct LaunchOptions
{
    QString rootFile;                 ///< workspace-relative; "" = every top-level launch file
    QMap<QString, QString> arguments; ///< name -> value (`--launch-arg name:=value`)
    QList<ExpectedExternal> externals = {};
    bool operator==(const LaunchOptions &) const = default;
};

/// Stage 2: finds launch files by content, reads them (Python, XML, YAML), and executes their
/// descriptions symbolically: arguments, scopes, namespaces, remaps, conditions, includes
/// (resolved through the workspace's packages, cycles reported), composable containers.
/// Node instances are resolved against stage 1's executables and plugins.
class LaunchAnalyzer
{
public:
    /// With `readAhead`, the launch files it read (when it did) are not read again.
    /// `resultKey` (when given) is set to a key the result is a function of, together with
    /// `nodes` (its memo's key and the files it read outside the scan; "" without the cache).
    static LaunchDependencies run(const Workspace &workspace, const AtomicNodeList &nodes,
                                  const LaunchOptions &options = {},
                                  const StageControl &control = {},
                                  LaunchReadAhead *readAhead = nullptr,
                                  QByteArray *resultKey = nullptr);
    /// `content` read by the reader of the file's format (Python, XML, YAML) when it is a
    /// launch file of that format; none otherwise.
    static std::optional<LaunchFileDescription> read(const SourceFile &file,
                                                     const QByteArray &content);
};

/// Convenience for a re-run of stage 2 alone: scans `root` again (fast) and runs the analyzer
/// against stage 1's result.
LaunchDependencies analyzeLaunchFiles(const QString &root, const AtomicNodeList &nodes,
                                      const LaunchOptions &options = {},
                                      const StageControl &control = {});

} // namespace rosarch
