#pragma once

#include "core/atomicnodelist.h"
#include "core/launchaction.h"
#include "core/launchdependencies.h"
#include "workspace/workspace.h"

#include <QHash>
#include <QList>

namespace rosarch {

/// Executables that build a system of their own (blueprint §1, "Nodes built in code"): a main
/// that constructs several node classes and hands them to an executor. Each is run as if a
/// launch file (its main source) held one Node action of it: as a root and entry point of the
/// system, and on its own for its CCD (the system `ros2 run pkg exe` starts).
class ExecutableSystems
{
public:
    ExecutableSystems(const Workspace &workspace, const AtomicNodeList &nodes);

    /// The launch description standing for the executable whose main is `file`, or null.
    const LaunchFileDescription *find(const QString &file) const;
    /// The main files, in package and executable order.
    const QStringList &files() const { return m_files; }
    /// Marks the instances of those files as executables: format "executable", type the
    /// executable's name, package its package.
    void mark(QList<LaunchFileInstance> *instances) const;

private:
    struct System
    {
        QString package;
        QString executable;
        LaunchFileDescription description;
    };
    QHash<QString, System> m_systems;
    QStringList m_files;
};

} // namespace rosarch
