#pragma once

#include "core/composition.h"
#include "core/launchdependencies.h"

#include <QList>
#include <QString>

namespace rosarch {

/// A root launch file of the architecture, as the diagram's root picker lists it.
struct LaunchRoot
{
    QString instanceId;      ///< the root's launch-file instance ("lf1")
    QString stem;            ///< "bringup" for bringup_launch.py
    QString file;            ///< workspace-relative ("" when unknown)
    int includes = 0;        ///< launch files it includes, transitively
    int nodes = 0;           ///< node instances it starts, transitively
    int unresolved = 0;      ///< things the analysis could not decide in it and its includes
    bool executable = false; ///< an executable that builds its own nodes, not a launch file
    bool operator==(const LaunchRoot &) const = default;
};

/// Which root the composed diagram starts on, and why.
struct RootChoice
{
    enum class Reason
    {
        None,       ///< no root at all
        Remembered, ///< a person chose it before (or the project's launch root)
        Only,       ///< the only root
        Name,       ///< its stem (or its folder) is or contains "bringup", "robot" or "system"
        Includes,   ///< it includes the most other launch files
        Ask         ///< several roots and no signal: ask the person (instanceId is "")
    };
    QString instanceId;
    Reason reason = Reason::None;

    /// The roots of `architecture` (composites without a parent) in its order, with the
    /// launch files they include and the nodes they start, transitively, and what `launch`
    /// (may be empty) says they leave unresolved.
    static QList<LaunchRoot> roots(const Architecture &architecture,
                                   const LaunchDependencies &launch);
    /// The root a person most likely wants to see first: the one whose file is `remembered`
    /// (workspace-relative), else the only one; else, among systems before tests, benchmarks,
    /// tools and examples: one whose stem is or contains "bringup", "robot" or "system" (exact
    /// before contained, then shallower path, fewer unresolved), else one in a folder named so
    /// (the one including the most), else the unique one including the most others; else none
    /// (Ask). Pure: the same roots always give the same choice.
    static RootChoice choose(const QList<LaunchRoot> &roots, const QString &remembered = {});
};

} // namespace rosarch
