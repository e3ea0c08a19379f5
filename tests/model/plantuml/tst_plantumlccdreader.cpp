// The PlantUML reader on CCDs: our notation, subsystems, and every hand-written variant
// blueprint §3 tolerates (stereotypes, arrows, colours, boundary port types, aliases).
#include "plantuml/plantumlreader.h"
#include "plantuml/umlmodel.h"
#include "support/testsupport.h"
#include "support/umltestsupport.h"

#include <QtTest>

using namespace rosarch;
using namespace rosarch::test::uml;

class TestPlantUmlCcdReader : public QObject
{
    Q_OBJECT
private Q_SLOTS:
    void ourCcd()
    {
        const UmlDiagram d = readOne(QString::fromUtf8(kCcd));
        QCOMPARE(d.level, UmlLevel::Ccd);
        QCOMPARE(d.name, QStringLiteral("demo"));
        QCOMPARE(describe(d), sorted(kCcdElements));
        QCOMPARE(d.notes, QStringList{QStringLiteral(
                              "line 19: launch stem 'sensors.launch.py' read as sensors")});
        QCOMPARE(d.warnings, QStringList());
    }

    void ccdWithSubsystemsReadsLikeWithout()
    {
        // Our writer's accepted groupings: <<Subsystem>> components around parts, inside a
        // namespace package and at the root. They add structure but no element, change no
        // namespace, and are not taken for parts.
        const UmlDiagram d = readOne(QStringLiteral(R"uml(@startuml
component "demo" as demo <<ComposedRosNodeClassifier>> {
  portin "s1 / sensor_msgs::msg::LaserScan" as b_s1
  portout "p1 / std_msgs::msg::String" as b_p1
  package "robot1" as ns_robot1 <<namespace>> {
    component "talking" as sub_talking <<Subsystem>> {
      component "talker:\nTalker" as part1 <<RosNodePart>> {
        portin "s1" as part1_s1
        portout "p1" as part1_p1
      }
    }
  }
  component "listening" as sub_listening <<Subsystem>> {
    component "listener:\nListener" as part2 <<RosNodePart>> {
      portin "s1" as part2_s1
      portout "p1" as part2_p1
    }
  }
  queue "/chatter" as q_chatter
  part1_p1 --[#Green,bold]--> q_chatter
  q_chatter --[#Blue,bold]--> part2_s1
  b_s1 --[#Blue,bold]--> part1_s1
  part2_p1 --[#Green,bold]--> b_p1
}
@enduml
)uml"));
        QCOMPARE(d.level, UmlLevel::Ccd);
        QCOMPARE(d.name, QStringLiteral("demo"));
        QCOMPARE(
            describe(d),
            sorted({QStringLiteral("part=talker"), QStringLiteral("part=listener"),
                    QStringLiteral("part_type=talker:Talker"),
                    QStringLiteral("part_type=listener:Listener"),
                    QStringLiteral("namespace=(robot1, talker)"),
                    QStringLiteral("namespace=(/, listener)"), QStringLiteral("topic=chatter"),
                    QStringLiteral("boundary_port=(in, sensor_msgs/msg/LaserScan)"),
                    QStringLiteral("boundary_port=(out, std_msgs/msg/String)"),
                    QStringLiteral("connection=publish talker -> chatter"),
                    QStringLiteral("connection=subscribe chatter -> listener"),
                    QStringLiteral(
                        "connection=delegation boundary:in/sensor_msgs/msg/LaserScan -> talker"),
                    QStringLiteral(
                        "connection=delegation listener -> boundary:out/std_msgs/msg/String")}));
        QCOMPARE(d.notes, QStringList());
        QCOMPARE(d.warnings, QStringList());
    }

    void ccdVariants_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QStringList>("elements");
        QTest::addColumn<QStringList>("notes");
        QTest::addColumn<QStringList>("warnings");
        const QStringList parts = {QStringLiteral("part=talker"),
                                   QStringLiteral("part=listener"),
                                   QStringLiteral("part_type=talker:Talker"),
                                   QStringLiteral("part_type=listener:Listener"),
                                   QStringLiteral("topic=chatter"),
                                   QStringLiteral("service=reset")};
        const QStringList root = {QStringLiteral("namespace=(/, talker)"),
                                  QStringLiteral("namespace=(/, listener)")};
        const QString declarations = QStringLiteral(R"uml(@startuml
component "<<ComposedRosNodeClassifier>>\ndemo.launch.py" as demo {
  component "<<rosnodepart>>\ntalker:\nTalker" as part1 {
    portout "p1" as part1_p1
    portout "rs1" as part1_rs1
  }
  component "listener:\nListener" as part2 <<RosNodePart>> {
    portin "s1" as part2_s1
    portin "ps1" as part2_ps1
  }
  queue "chatter" as q_chatter
  circle "reset" as c_reset <<service>>
)uml");
        const QStringList declarationNotes = {
            QStringLiteral("line 2: launch stem 'demo.launch.py' read as demo"),
            QStringLiteral("line 3: stereotype 'rosnodepart' read as RosNodePart"),
            QStringLiteral("line 12: stereotype 'service' read as Service")};

        QTest::newRow("stereotypes in labels and cased, no colours, arrows either way round")
            << declarations + QStringLiteral(R"uml(  q_chatter <-- part1_p1
  part2_s1 <-[#blue]- q_chatter
  c_reset <--- part1_rs1
  part2_ps1 -- c_reset
}
@enduml
)uml")
            << parts + root +
                   QStringList{QStringLiteral("connection=publish talker -> chatter"),
                               QStringLiteral("connection=subscribe chatter -> listener"),
                               QStringLiteral("connection=client talker -> reset"),
                               QStringLiteral("connection=server listener -> reset")}
            << declarationNotes +
                   QStringList{
                       QStringLiteral(
                           "line 13: connection kind 'publish' inferred from the arrow ends"),
                       QStringLiteral(
                           "line 15: connection kind 'client' inferred from the arrow ends"),
                       QStringLiteral(
                           "line 16: connection kind 'server' inferred from the arrow ends")}
            << QStringList();
        // Our writer names a part's port after its id, on a line of its own: the id still
        // tells a server from a client.
        QString named = declarations;
        for (const auto &[id, name] : {std::pair{"p1", "chatter"}, std::pair{"rs1", "reset ?"},
                                       std::pair{"s1", "chatter"}, std::pair{"ps1", "/reset"}})
            named.replace(
                QStringLiteral("\"%1\" as").arg(QLatin1String(id)),
                QStringLiteral("\"%1\\n%2\" as").arg(QLatin1String(id), QLatin1String(name)));
        QVERIFY(named.contains(QLatin1String(R"("ps1\n/reset" as part2_ps1)")));
        QTest::newRow("part ports named after their ids, no colours")
            << named + QStringLiteral(R"uml(  q_chatter <-- part1_p1
  part2_s1 <-[#blue]- q_chatter
  c_reset <--- part1_rs1
  part2_ps1 -- c_reset
}
@enduml
)uml")
            << parts + root +
                   QStringList{QStringLiteral("connection=publish talker -> chatter"),
                               QStringLiteral("connection=subscribe chatter -> listener"),
                               QStringLiteral("connection=client talker -> reset"),
                               QStringLiteral("connection=server listener -> reset")}
            << declarationNotes +
                   QStringList{
                       QStringLiteral(
                           "line 13: connection kind 'publish' inferred from the arrow ends"),
                       QStringLiteral(
                           "line 15: connection kind 'client' inferred from the arrow ends"),
                       QStringLiteral(
                           "line 16: connection kind 'server' inferred from the arrow ends")}
            << QStringList();
        QTest::newRow("colour decides over the arrow ends, any case, any dashes")
            << declarations + QStringLiteral(R"uml(  part1_p1 -[#BLUE,bold]----> q_chatter
  q_chatter -[#00FF00]-> part2_s1
  part1_rs1 -[bold,#purple]-> c_reset
}
@enduml
)uml")
            << parts + root +
                   QStringList{QStringLiteral("connection=subscribe chatter -> talker"),
                               QStringLiteral("connection=publish listener -> chatter"),
                               QStringLiteral("connection=server talker -> reset")}
            << declarationNotes +
                   QStringList{QStringLiteral("line 13: colour says 'subscribe' but the arrow ends "
                                              "say 'publish'; the colour is read"),
                               QStringLiteral("line 14: colour says 'publish' but the arrow ends "
                                              "say 'subscribe'; the colour is read"),
                               QStringLiteral("line 15: colour says 'server' but the arrow ends "
                                              "say 'client'; the colour is read")}
            << QStringList();
        QTest::newRow("undeclared arrow ends and parts joined to parts")
            << declarations + QStringLiteral(R"uml(  part1_p1 --> q_missing
  part1 --> part2
}
@enduml
)uml") << parts + root + QStringList{QStringLiteral("connection=link talker -> listener")}
            << declarationNotes
            << QStringList{
                   QStringLiteral("line 13: arrow end 'q_missing' is not declared; arrow ignored")};
        QTest::newRow(
            "packages without <<namespace>>, qualified and unnamed parts, no top component")
            << QStringLiteral(R"uml(@startuml
title bringup
package "/robot" {
  package "left" as ns_left {
    component ":Talker" as t <<RosNodePart>>
  }
}
component "/other/listener:Listener" as l <<RosNodePart>> {
  portin "s1 / std_msgs::msg::String" as l_s1
}
component "/n2:Listener" as l2 <<RosNodePart>>
@enduml
)uml")
            << QStringList{QStringLiteral("part=Talker"),
                           QStringLiteral("part=listener"),
                           QStringLiteral("part=n2"),
                           QStringLiteral("part_type=:Talker"),
                           QStringLiteral("part_type=listener:Listener"),
                           QStringLiteral("part_type=n2:Listener"),
                           QStringLiteral("namespace=(robot/left, Talker)"),
                           QStringLiteral("namespace=(other, listener)"),
                           QStringLiteral("namespace=(/, n2)")}
            << QStringList{QStringLiteral("line 1: diagram named 'bringup' after its title"),
                           QStringLiteral("line 3: package '/robot' without <<namespace>> read as "
                                          "a namespace"),
                           QStringLiteral(
                               "line 4: package 'left' without <<namespace>> read as a namespace"),
                           QStringLiteral("line 5: no <<ComposedRosNodeClassifier>>; read as a CCD "
                                          "because of its "
                                          "<<RosNodePart>>s"),
                           QStringLiteral("line 8: part name 'other/listener' read as listener in "
                                          "namespace other")}
            << QStringList();
    }

    void ccdVariants()
    {
        QFETCH(QString, text);
        QFETCH(QStringList, elements);
        QFETCH(QStringList, notes);
        QFETCH(QStringList, warnings);
        const UmlDiagram d = readOne(text);
        QCOMPARE(d.level, UmlLevel::Ccd);
        QVERIFY(d.name == QLatin1String("demo") || d.name == QLatin1String("bringup"));
        QCOMPARE(describe(d), sorted(elements));
        QCOMPARE(d.notes, notes);
        QCOMPARE(d.warnings, warnings);
    }

    void boundaryPortTypes()
    {
        // The boundary port's id says which kind of type `pkg/T` is; `port` takes its direction
        // from the id too.
        const UmlDiagram d = readOne(QStringLiteral(R"uml(@startuml
component "demo" as demo <<ComposedRosNodeClassifier>> {
  portin "ps1 / std_srvs/Trigger" as b_ps1
  portout "ra1\nnav2_msgs::NavigateToPose" as b_ra1
  port "s2 / sensor_msgs/msg/Imu" as b_s2
  portin "std_msgs::msg::String" as b_s3
  portout "p4 /geometry_msgs::msg::Twist" as b_p4
  portout "p5/ geometry_msgs::msg::Twist" as b_p5
}
@enduml
)uml"));
        QCOMPARE(d.level, UmlLevel::Ccd);
        QCOMPARE(d.values(UmlKind::BoundaryPort),
                 (QStringList{QStringLiteral("(in, std_srvs/srv/Trigger)"),
                              QStringLiteral("(out, nav2_msgs/action/NavigateToPose)"),
                              QStringLiteral("(in, sensor_msgs/msg/Imu)"),
                              QStringLiteral("(in, std_msgs/msg/String)"),
                              QStringLiteral("(out, geometry_msgs/msg/Twist)"),
                              QStringLiteral("(out, geometry_msgs/msg/Twist)")}));
        QCOMPARE(d.notes,
                 (QStringList{
                     QStringLiteral("line 3: type 'std_srvs/Trigger' read as std_srvs/srv/Trigger"),
                     QStringLiteral("line 4: type 'nav2_msgs::NavigateToPose' read as "
                                    "nav2_msgs/action/NavigateToPose"),
                     QStringLiteral("line 5: port s2 read as direction in")}));
        QCOMPARE(d.warnings, QStringList());
    }

    void portAliasesResolveThroughDeclarations()
    {
        // `part10_s1` starts like part1's ports: only the declarations say whose port it is.
        const UmlDiagram d = readOne(QStringLiteral(R"uml(@startuml
component "launch" as launch <<ComposedRosNodeClassifier>> {
  component "a:A" as part1 <<RosNodePart>> {
    portout "p1" as part1_0_p1
  }
  component "b:B" as part10 <<RosNodePart>> {
    portin "s1" as part1_s1
  }
  queue "/t" as q
  part1_0_p1 -[#green]-> q
  q -[#blue]-> part1_s1
}
@enduml
)uml"));
        QCOMPARE(d.values(UmlKind::Connection), (QStringList{QStringLiteral("publish a -> t"),
                                                             QStringLiteral("subscribe t -> b")}));
    }

    void bareLabelNamingAClassifierIsTheType()
    {
        // Blueprint §3: "Talker" names the model's ACD, so it is the part's type; "lidar"
        // names nothing and stays a name. A model's own name does not type its parts.
        QList<UmlDiagram> model = PlantUmlReader::read(QStringLiteral(R"uml(@startuml
component "<<AtomicRosNodeClassifier>>\nTalker" as node {
  portout " " as p1
}
@enduml
@startuml
component "demo" as demo <<ComposedRosNodeClassifier>> {
  component "Talker" as part1 <<RosNodePart>>
  component "lidar" as part2 <<RosNodePart>>
  component "demo" as part3 <<RosNodePart>>
}
@enduml
)uml"));
        QCOMPARE(model.size(), 2);
        UmlModel::typeByClassifiers(&model);
        const UmlDiagram &d = model.at(1);
        QCOMPARE(d.values(UmlKind::Part),
                 (QStringList{QStringLiteral("Talker"), QStringLiteral("lidar"),
                              QStringLiteral("demo")}));
        QCOMPARE(d.values(UmlKind::PartType), QStringList{QStringLiteral(":Talker")});
        QCOMPARE(d.notes,
                 (QStringList{QStringLiteral("line 8: part label 'Talker' has no ':' and names a "
                                             "classifier of the model; read as the part's type"),
                              QStringLiteral("line 9: part label 'lidar' has no ':'; read as the "
                                             "name"),
                              QStringLiteral("line 10: part label 'demo' has no ':'; read as the "
                                             "name")}));
        QVERIFY(d.bareParts.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestPlantUmlCcdReader)
#include "tst_plantumlccdreader.moc"
