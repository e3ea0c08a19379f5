#pragma once

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"
#include "project/stablekeys.h"

#include <QHash>
#include <QString>

namespace rosarch {

/// Carries corrections into the launch files' own classifiers (blueprint §1, "The CCD of a
/// launch file is its classifier"). A person names topics, services and actions as the system
/// shows them: resolved in the instance's namespace ("/robot1/odom"). A classifier is the same
/// launch file analysed in the root namespace, where that channel is spelled otherwise ("odom",
/// "robot1/odom"). Without this, an added connection or a renamed topic is wired in the system
/// but left unconnected on the boundary of the CCD and the Mermaid diagram.
class ClassifierCorrections
{
public:
    /// `name`, given for a node instance in `systemNamespace`, relative to that instance
    /// ("/robot1/odom" in "/robot1" is "odom") when it lies in its namespace; else (and in the
    /// root namespace, where nothing tells) as given. A node's copy in a classifier resolves it
    /// in its own namespace to the same channel.
    static QString relativeTo(const QString &name, const QString &systemNamespace);

    /// `name` (given for an instance in `systemNamespace`) as the instance's copy in a
    /// classifier, in the scope-relative `classifierNamespace`, spells it.
    static QString carried(const QString &name, const QString &systemNamespace,
                           const QString &classifierNamespace);

    /// Composes again the classifiers of `architecture` whose ports talk on a channel that
    /// `renamed` (channel key -> new name, in the system's names) renamed, with the rename
    /// spelled as each classifier spells that channel. `keys` finds an instance's copies.
    static void rename(Architecture *architecture, const AtomicNodeList &nodes,
                       const LaunchDependencies &launch, const QHash<QString, QString> &renamed,
                       const StableKeys &keys);
};

} // namespace rosarch
