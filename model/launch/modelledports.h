#pragma once

#include "core/launchdependencies.h"

#include <QByteArray>
#include <QHash>
#include <QString>
#include <QStringList>

#include <functional>

namespace rosarch {

/// The ports interface models give what a launch file starts or includes from outside the
/// workspace (blueprint §1): a model's own ports, and those of a configuration file the node's
/// command line names (rviz2 -d file.rviz), each file read once per run.
class ModelledPorts
{
public:
    /// A path as the launch file evaluates it -> the workspace file ("" when outside).
    using Resolve = std::function<QString(const QString &path)>;

    explicit ModelledPorts(QString workspaceRoot);

    /// Gives `n`, a node of a package outside the workspace, the ports of the model of its
    /// executable, if one describes it. `commandLine` is the node's evaluated arguments.
    void forNode(NodeInstance *n, const QStringList &commandLine, const Evidence &evidence,
                 const Resolve &resolve, QList<Diagnostic> *diagnostics);
    /// Gives `inst`, an include of an external launch file (`shareRelative` in `package`) with
    /// its evaluated arguments, the ports of the model of that file, if one describes it,
    /// under `scopeNamespace` and the value passed for the model's namespace argument.
    static void forInclude(LaunchFileInstance *inst, const QString &package,
                           const QString &shareRelative, const QString &scopeNamespace);

private:
    QString m_root;
    QHash<QString, QByteArray> m_configFiles; ///< workspace-relative path -> content
};

} // namespace rosarch
