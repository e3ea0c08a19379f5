#pragma once

// A hand-made stage 3 result for the diagram tests: a root launch file including a child, with
// namespaces, a topic, a service, an action, boundary ports, an inactive part and an external
// include. Included by tst_graphlayout.cpp and tst_diagrampanel.cpp.
#include "core/composition.h"

#include <QMap>

namespace rosarch::test::diagram {

inline PartPort port(const QString &id, PortKind kind, const QString &written, const QString &name,
                     const QString &type, int line)
{
    PartPort p;
    p.id = id;
    p.kind = kind;
    p.nameAsWritten = written;
    p.name = name;
    p.type = type;
    p.evidence = {QStringLiteral("src/demo/demo/talker.py"), line, 5, line, 60};
    return p;
}

inline RosNodePart part(const QString &id, RosNodePart::Kind kind, const QString &instanceId,
                        const QString &name, const QString &typeName, const QString &nameSpace,
                        QList<PartPort> ports, int line)
{
    RosNodePart p;
    p.id = id;
    p.kind = kind;
    p.instanceId = instanceId;
    p.name = name;
    p.typeName = typeName;
    p.typeId = kind == RosNodePart::Kind::Node ? QStringLiteral("arc_") + id : instanceId;
    p.nameSpace = nameSpace;
    p.ports = std::move(ports);
    p.evidence = {QStringLiteral("src/demo/launch/demo.launch.py"), line, 9, line + 2, 40};
    return p;
}

inline Connection connect(Connection::Kind kind, const QString &partId, const QString &portId,
                          const QString &target)
{
    return {kind, partId, portId, target};
}

inline Architecture architecture()
{
    using K = Connection::Kind;
    const QString msg = QStringLiteral("std_msgs/msg/String");
    const QString srv = QStringLiteral("std_srvs/srv/Trigger");
    const QString action = QStringLiteral("nav2_msgs/action/NavigateToPose");

    Composite root;
    root.instanceId = QStringLiteral("lf1");
    root.stem = QStringLiteral("demo");
    root.file = QStringLiteral("src/demo/launch/demo.launch.py");
    root.package = QStringLiteral("demo");

    PartPort echo = port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("echo"),
                         QStringLiteral("/echo"), msg, 12);
    echo.parameterDerived = true;
    PartPort goal = port(QStringLiteral("ra1"), PortKind::ActionClient, QStringLiteral("navigate"),
                         QStringLiteral("/navigate"), action, 14);
    root.parts << part(QStringLiteral("part1"), RosNodePart::Kind::Node, QStringLiteral("n1"),
                       QStringLiteral("talker"), QStringLiteral("Talker"), QStringLiteral("/"),
                       {port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("chatter"),
                             QStringLiteral("/chatter"), msg, 11),
                        echo,
                        port(QStringLiteral("rs1"), PortKind::ServiceClient,
                             QStringLiteral("reset"), QStringLiteral("/reset"), srv, 13),
                        goal},
                       18);
    root.parts << part(
        QStringLiteral("part2"), RosNodePart::Kind::Launch, QStringLiteral("lf2"), {},
        QStringLiteral("listener"), QStringLiteral("/robot1"),
        {port(QStringLiteral("s1"), PortKind::Subscriber, {}, QStringLiteral("/chatter"), msg, 3),
         port(QStringLiteral("ps1"), PortKind::ServiceServer, {}, QStringLiteral("/reset"), srv,
              4)},
        23);
    RosNodePart echoTalker = part(
        QStringLiteral("part3"), RosNodePart::Kind::Node, QStringLiteral("n4"),
        QStringLiteral("echo_talker"), QStringLiteral("Talker"), QStringLiteral("/robot1/extra"),
        {port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("chatter"),
              QStringLiteral("/robot1/extra/chatter"), msg, 11)},
        28);
    echoTalker.active = false;
    root.parts << echoTalker;
    RosNodePart navigator =
        part(QStringLiteral("part4"), RosNodePart::Kind::Node, QStringLiteral("n5"),
             QStringLiteral("navigator"), QStringLiteral("Navigator"), QStringLiteral("/robot1"),
             {port(QStringLiteral("pa1"), PortKind::ActionServer, QStringLiteral("/navigate"),
                   QStringLiteral("/navigate"), action, 30)},
             31);
    root.parts << navigator;
    RosNodePart external =
        part(QStringLiteral("part5"), RosNodePart::Kind::Launch, QStringLiteral("lf3"), {},
             QStringLiteral("talker"), QStringLiteral("/"), {}, 35);
    external.external = true;
    root.parts << external;

    root.channels = {
        {QStringLiteral("q_chatter"), Channel::Kind::Topic, QStringLiteral("/chatter"), msg},
        {QStringLiteral("c_reset"), Channel::Kind::Service, QStringLiteral("/reset"), srv},
        {QStringLiteral("a_navigate"), Channel::Kind::Action, QStringLiteral("/navigate"), action}};
    root.boundary = {
        {QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("/echo"), msg},
        {QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("/robot1/extra/chatter"), msg}};
    root.connections = {connect(K::Publish, QStringLiteral("part1"), QStringLiteral("p1"),
                                QStringLiteral("q_chatter")),
                        connect(K::Subscribe, QStringLiteral("part2"), QStringLiteral("s1"),
                                QStringLiteral("q_chatter")),
                        connect(K::Client, QStringLiteral("part1"), QStringLiteral("rs1"),
                                QStringLiteral("c_reset")),
                        connect(K::Server, QStringLiteral("part2"), QStringLiteral("ps1"),
                                QStringLiteral("c_reset")),
                        connect(K::Client, QStringLiteral("part1"), QStringLiteral("ra1"),
                                QStringLiteral("a_navigate")),
                        connect(K::Server, QStringLiteral("part4"), QStringLiteral("pa1"),
                                QStringLiteral("a_navigate")),
                        connect(K::DelegationIn, QStringLiteral("part1"), QStringLiteral("s1"),
                                QStringLiteral("s1")),
                        connect(K::DelegationOut, QStringLiteral("part3"), QStringLiteral("p1"),
                                QStringLiteral("p1"))};

    Composite child;
    child.instanceId = QStringLiteral("lf2");
    child.stem = QStringLiteral("listener");
    child.file = QStringLiteral("src/demo/launch/listener.launch.xml");
    child.package = QStringLiteral("demo");
    child.parentId = root.instanceId;
    PartPort unresolved =
        port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("topic_name"),
             QStringLiteral("/robot1/topic_name"), msg, 21);
    unresolved.resolved = false;
    child.parts << part(QStringLiteral("part1"), RosNodePart::Kind::Node, QStringLiteral("n2"),
                        QStringLiteral("listener"), QStringLiteral("Listener"),
                        QStringLiteral("/robot1"),
                        {port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("chatter"),
                              QStringLiteral("/chatter"), msg, 17),
                         port(QStringLiteral("ps1"), PortKind::ServiceServer,
                              QStringLiteral("/reset"), QStringLiteral("/reset"), srv, 19),
                         unresolved},
                        3);
    child.boundary = {
        {QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("/chatter"), msg},
        {QStringLiteral("ps1"), PortKind::ServiceServer, QStringLiteral("/reset"), srv},
        {QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("/robot1/topic_name"), msg}};
    child.connections = {connect(K::DelegationIn, QStringLiteral("part1"), QStringLiteral("s1"),
                                 QStringLiteral("s1")),
                         connect(K::DelegationIn, QStringLiteral("part1"), QStringLiteral("ps1"),
                                 QStringLiteral("ps1")),
                         connect(K::DelegationOut, QStringLiteral("part1"), QStringLiteral("p1"),
                                 QStringLiteral("p1"))};

    Architecture arch;
    arch.composites = {root, child};
    return arch;
}

/// Wires the parts of `c` the way the composer does, simplified: ports with the same name and
/// opposite kinds meet at a channel; a port with no counterpart becomes a boundary port.
inline void wire(Composite &c)
{
    using K = Connection::Kind;
    QMap<QString, QList<std::pair<const RosNodePart *, const PartPort *>>> byName;
    for (const RosNodePart &part : c.parts)
        for (const PartPort &port : part.ports)
            byName[port.name] << std::make_pair(&part, &port);
    QList<Connection> connections;
    for (auto it = byName.cbegin(); it != byName.cend(); ++it) {
        bool in = false;
        bool out = false;
        for (const auto &[part, port] : it.value()) {
            const bool input = port->kind == PortKind::Subscriber ||
                               port->kind == PortKind::ServiceServer ||
                               port->kind == PortKind::ActionServer;
            (input ? in : out) = true;
        }
        const PortKind kind = it.value().first().second->kind;
        const bool service = kind == PortKind::ServiceServer || kind == PortKind::ServiceClient;
        const bool action = kind == PortKind::ActionServer || kind == PortKind::ActionClient;
        QString alias = it.key();
        alias.replace(QLatin1Char('/'), QLatin1Char('_'));
        if (in && out) {
            const QString id = (service  ? QStringLiteral("c")
                                : action ? QStringLiteral("a")
                                         : QStringLiteral("q")) +
                               alias;
            c.channels << Channel{id,
                                  service  ? Channel::Kind::Service
                                  : action ? Channel::Kind::Action
                                           : Channel::Kind::Topic,
                                  it.key(), it.value().first().second->type};
            for (const auto &[part, port] : it.value()) {
                K k = K::Publish;
                switch (port->kind) {
                case PortKind::Publisher:
                    k = K::Publish;
                    break;
                case PortKind::Subscriber:
                    k = K::Subscribe;
                    break;
                case PortKind::ServiceClient:
                case PortKind::ActionClient:
                    k = K::Client;
                    break;
                case PortKind::ServiceServer:
                case PortKind::ActionServer:
                    k = K::Server;
                    break;
                }
                connections << Connection{k, part->id, port->id, id};
            }
        } else {
            const QString id = QStringLiteral("b%1").arg(c.boundary.size() + 1);
            c.boundary << BoundaryPort{id, kind, it.key(), it.value().first().second->type};
            for (const auto &[part, port] : it.value())
                connections << Connection{in ? K::DelegationIn : K::DelegationOut, part->id,
                                          port->id, id};
        }
    }
    c.connections = connections;
}

/// A bigger composite: per robot namespace a driver, a lidar in a nested namespace, a
/// localizer and a planner; at the root a map server and a fleet monitor.
inline Composite fleet(int robots)
{
    const QString odom = QStringLiteral("nav_msgs/msg/Odometry");
    const QString twist = QStringLiteral("geometry_msgs/msg/Twist");
    const QString pose = QStringLiteral("geometry_msgs/msg/PoseStamped");
    const QString scan = QStringLiteral("sensor_msgs/msg/LaserScan");
    const QString map = QStringLiteral("nav_msgs/msg/OccupancyGrid");
    const QString trigger = QStringLiteral("std_srvs/srv/Trigger");
    Composite c;
    c.instanceId = QStringLiteral("lf9");
    c.stem = QStringLiteral("fleet");
    c.file = QStringLiteral("src/fleet/launch/fleet.launch.py");
    int n = 0;
    const auto add = [&](const QString &name, const QString &type, const QString &ns,
                         QList<PartPort> ports) {
        ++n;
        c.parts << part(QStringLiteral("part%1").arg(n), RosNodePart::Kind::Node,
                        QStringLiteral("n%1").arg(n), name, type, ns, std::move(ports), 10 + n);
    };
    add(QStringLiteral("map_server"), QStringLiteral("MapServer"), QStringLiteral("/"),
        {port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("map"),
              QStringLiteral("/map"), map, 5),
         port(QStringLiteral("ps1"), PortKind::ServiceServer, QStringLiteral("~/reload"),
              QStringLiteral("/map_server/reload"), trigger, 6)});
    QList<PartPort> monitor{
        port(QStringLiteral("rs1"), PortKind::ServiceClient, QStringLiteral("/map_server/reload"),
             QStringLiteral("/map_server/reload"), trigger, 7),
        port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("status"),
             QStringLiteral("/fleet/status"), QStringLiteral("std_msgs/msg/String"), 8)};
    for (int r = 1; r <= robots; ++r) {
        const QString ns = QStringLiteral("/robot%1").arg(r);
        add(QStringLiteral("driver"), QStringLiteral("DiffDriver"), ns,
            {port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("cmd_vel"),
                  ns + QStringLiteral("/cmd_vel"), twist, 3),
             port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("odom"),
                  ns + QStringLiteral("/odom"), odom, 4)});
        add(QStringLiteral("lidar"), QStringLiteral("LidarDriver"), ns + QStringLiteral("/sensors"),
            {port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("/scan"),
                  ns + QStringLiteral("/scan"), scan, 3)});
        add(QStringLiteral("localizer"), QStringLiteral("AmclNode"), ns,
            {port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("odom"),
                  ns + QStringLiteral("/odom"), odom, 3),
             port(QStringLiteral("s2"), PortKind::Subscriber, QStringLiteral("scan"),
                  ns + QStringLiteral("/scan"), scan, 4),
             port(QStringLiteral("s3"), PortKind::Subscriber, QStringLiteral("/map"),
                  QStringLiteral("/map"), map, 5),
             port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("pose"),
                  ns + QStringLiteral("/pose"), pose, 6)});
        add(QStringLiteral("planner"), QStringLiteral("Planner"), ns,
            {port(QStringLiteral("s1"), PortKind::Subscriber, QStringLiteral("pose"),
                  ns + QStringLiteral("/pose"), pose, 3),
             port(QStringLiteral("s2"), PortKind::Subscriber, QStringLiteral("goal"),
                  ns + QStringLiteral("/goal"), pose, 4),
             port(QStringLiteral("p1"), PortKind::Publisher, QStringLiteral("cmd_vel"),
                  ns + QStringLiteral("/cmd_vel"), twist, 5)});
        monitor << port(QStringLiteral("s%1").arg(r), PortKind::Subscriber,
                        ns + QStringLiteral("/pose"), ns + QStringLiteral("/pose"), pose, 8 + r);
    }
    add(QStringLiteral("fleet_monitor"), QStringLiteral("FleetMonitor"), QStringLiteral("/"),
        monitor);
    wire(c);
    return c;
}

} // namespace rosarch::test::diagram
