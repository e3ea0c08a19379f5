#pragma once

// Shared by the PlantUML reader tests: the canonical view of a diagram and our own notation.
#include "plantuml/plantumlreader.h"
#include "plantuml/umldiagram.h"

#include <QString>
#include <QStringList>

namespace rosarch::test::uml {

/// "kind=value" per element, sorted: the canonical multiset.
inline QStringList describe(const UmlDiagram &d)
{
    QStringList out;
    for (const UmlElement &e : d.elements)
        out << e.kind + QLatin1Char('=') + e.value;
    out.sort();
    return out;
}

inline QStringList sorted(QStringList list)
{
    list.sort();
    return list;
}

inline UmlDiagram readOne(const QString &text)
{
    const QList<UmlDiagram> all =
        PlantUmlReader::read(text, QStringLiteral("/refs/some_file.puml"));
    return all.size() == 1 ? all.first() : UmlDiagram{};
}

inline const char *const kAcd = R"uml(@startuml
component "<<AtomicRosNodeClassifier>>\nTalker" as node {
  portin "on_cmd" as s1
  portout " " as p1
}
frame "s1\ncmd" as topic_s1 {
  rectangle "**geometry_msgs::msg::Twist**" as t_s1
}
frame "p1\nchatter" as topic_p1 {
  rectangle "**std_msgs::msg::String**" as t_p1
}
folder "ps1\nreset" as srv_ps1 {
  rectangle "**std_srvs::srv::Trigger**" as st_ps1
  rectangle "on_reset(...)" as sf_ps1
}
topic_s1 -[#blue,bold]-> s1
p1 -[#green,bold]-> topic_p1
node --0 srv_ps1
@enduml
)uml";

inline const QStringList kAcdElements = {QStringLiteral("arc_name=Talker"),
                                         QStringLiteral("arc_stereotype=AtomicRosNodeClassifier"),
                                         QStringLiteral("callback=on_cmd"),
                                         QStringLiteral("message_type=geometry_msgs/msg/Twist"),
                                         QStringLiteral("message_type=std_msgs/msg/String"),
                                         QStringLiteral("service_function=on_reset"),
                                         QStringLiteral("service_type=std_srvs/srv/Trigger")};

inline const char *const kCcd = R"uml(@startuml
component "demo" as demo <<ComposedRosNodeClassifier>> {
  portin "s1 / sensor_msgs::msg::LaserScan" as b_s1
  portout "p1 / std_msgs::msg::String" as b_p1
  package "robot1" as ns_robot1 <<namespace>> {
    component "talker:\nTalker" as part1 <<RosNodePart>> {
      portin "s1" as part1_s1
      portout "p1" as part1_p1
      portout "rs1" as part1_rs1
    }
    package "/abs" as ns_abs <<namespace>> {
      component "listener:\nListener" as part2 <<RosNodePart>> {
        portin "s1" as part2_s1
        portin "ps1" as part2_ps1
        portout "p1" as part2_p1
      }
    }
    package "inner" as ns_inner <<namespace>> {
      component ":sensors.launch.py" as part3 <<RosNodePart>> {
        portout "p1" as part3_p1
      }
    }
  }
  queue "/chatter" as q_chatter
  circle "/reset" as c_reset <<Service>>
  circle "/navigate" as a_navigate <<Action>>
  part1_p1 --[#Green,bold]--> q_chatter
  q_chatter --[#Blue,bold]--> part2_s1
  part1_rs1 --[#Red,bold]--> c_reset
  part2_ps1 --[#Purple,bold]--> c_reset
  b_s1 --[#Blue,bold]--> part1_s1
  part2_p1 --[#Green,bold]--> b_p1
}
@enduml
)uml";

inline const QStringList kCcdElements = {
    QStringLiteral("part=talker"),
    QStringLiteral("part=listener"),
    QStringLiteral("part=sensors"),
    QStringLiteral("part_type=talker:Talker"),
    QStringLiteral("part_type=listener:Listener"),
    QStringLiteral("part_type=:sensors"),
    QStringLiteral("namespace=(robot1, talker)"),
    QStringLiteral("namespace=(abs, listener)"),
    QStringLiteral("namespace=(robot1/inner, sensors)"),
    QStringLiteral("topic=chatter"),
    QStringLiteral("service=reset"),
    QStringLiteral("action=navigate"),
    QStringLiteral("boundary_port=(in, sensor_msgs/msg/LaserScan)"),
    QStringLiteral("boundary_port=(out, std_msgs/msg/String)"),
    QStringLiteral("connection=publish talker -> chatter"),
    QStringLiteral("connection=subscribe chatter -> listener"),
    QStringLiteral("connection=client talker -> reset"),
    QStringLiteral("connection=server listener -> reset"),
    QStringLiteral("connection=delegation boundary:in/sensor_msgs/msg/LaserScan -> talker"),
    QStringLiteral("connection=delegation listener -> boundary:out/std_msgs/msg/String")};

} // namespace rosarch::test::uml
