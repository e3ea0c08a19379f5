#pragma once

#include <QHash>

#include "core/atomicnodelist.h"
#include "core/composition.h"
#include "core/launchdependencies.h"
#include "core/stagecontrol.h"

namespace rosarch {

/// Stage 3: builds one ComposedRosNodeClassifier per launch-file instance from the atomic
/// nodes and the launch dependencies (blueprint §1): resolves every port's name for its
/// instance, evaluates guards, wires topics, services and actions inside each composite and
/// promotes what has no counterpart there to the composite's boundary.
class Composer
{
public:
    /// `renamed` maps channelKey(kind, resolved name) to the name a person gave the topic,
    /// service or action; every port that resolves to it is renamed before wiring.
    static Architecture run(const AtomicNodeList &nodes, const LaunchDependencies &launch,
                            const StageControl &control = {},
                            const QHash<QString, QString> &renamed = {});

    /// The ports of one node instance with names resolved (remaps, namespace, private names,
    /// parameter values) and guards evaluated; `container` supplies container-level remaps.
    static QList<PartPort> resolvePorts(const AtomicNode &node, const NodeInstance &instance,
                                        const NodeInstance *container,
                                        QList<int> *rulesUsed = nullptr);
    /// The ports of the pluginlib plugins the instance loads (its `plugins`), resolved as the
    /// instance's own, their ids prefixed by the plugin's name.
    static QList<PartPort> pluginPorts(const QHash<QString, const AtomicNode *> &pluginClasses,
                                       const NodeInstance &instance, const NodeInstance *container);
    /// Whether the port's guard is decided for the instance: there is none, or it reads one
    /// parameter whose value the instance gives or the declaration defaults. (A guard over
    /// several values, or an unknown one, leaves the port in place as the best guess.)
    static bool guardDecided(const Port &port, const NodeInstance &instance);
};

/// "topic:/scan", "service:/map/save", "action:/navigate": what a port of `kind` named
/// `name` talks on, as the stable key of that topic, service or action (blueprint §5).
QString channelKey(PortKind kind, const QString &name);

/// The launch file's stem: "robot" for robot.launch.py, "nav" for nav_launch.py.
QString launchStem(const QString &fileName);

} // namespace rosarch
