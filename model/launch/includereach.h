#pragma once

#include "launch/launchexecutor.h"

#include <QStringList>

namespace rosarch {

/// The launch files one include action reaches, as the entry points need them (a file that
/// no other file includes under any condition is an entry point, docs/checks.md): the target
/// when the include runs, or as included under a condition when it does not; and, when an
/// argument picks the package (`$(find-pkg-share $(var kit))/launch/x.launch.xml`, or a
/// variable made from an argument nobody sets), the same file of every package, since some
/// value of the argument includes it.
struct IncludeReach
{
    static void note(const LaunchAction &include, const IncludeTarget &target, bool active,
                     bool pathUndecided, const QStringList &launchFiles, QStringList *includes,
                     QStringList *conditional);
};

} // namespace rosarch
