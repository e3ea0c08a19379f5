#pragma once

#include <QHash>

#include "atomicnodelist.h"
#include "composition.h"
#include "launchdependencies.h"
#include "stagecontrol.h"

namespace rosarch {

/// Stage 3: builds one ComposedRosNodeClassifier per launch-file instance from the atomic
/// nodes and the launch dependencies (blueprint §1): resolves every port's name for its
/// instance, evaluates guards, wires topics, services and actions inside each composite and
/// promotes what has no counterpart there to the composite's boundary.
class Composer
{
public:
    static Architecture run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                            const StageControl &control = {});

    /// The ports of one node instance with names resolved (remaps, namespace, private names,
    /// parameter values) and guards evaluated; `container` supplies container-level remaps.
    static QList<PartPort> resolvePorts(const AtomicNode &node, const NodeInstance &instance,
                                        const NodeInstance *container,
                                        QList<int> *rulesUsed = nullptr);
    /// The ports of the pluginlib plugins the instance loads (its `plugins`), resolved as the
    /// instance's own, their ids prefixed by the plugin's name.
    static QList<PartPort> pluginPorts(const QHash<QString, const AtomicNode *> &pluginClasses,
                                       const NodeInstance &instance, const NodeInstance *container);
};

/// The launch file's stem: "robot" for robot.launch.py, "nav" for nav_launch.py.
QString launchStem(const QString &fileName);

} // namespace rosarch
